#pragma once
// Structural check of a BVH memory image (bvh_image.h) before a traversal reads it, on the words
// alone: no build tree or mesh is needed, so an image from a file is checked as one just laid
// out. The walk from the root uses an explicit stack and visits each node once, so any image,
// however corrupt, is checked in linear time.

#include <cstdint>
#include <string>
#include <vector>

#include "rtu/image_problems.h"

namespace rtu {

using BvhProblem =
    ImageProblem;  // "BVH word 23: node 0: ...", naming the node, reference or triangle

// Every problem found, in the order found: a header that is not this format or whose sections are
// not where bvhSections places them for its counts, or a size other than the header's (then
// nothing further is read); a child outside the nodes or reached a second time (a cycle or a
// shared node), a node reached from no parent, a box that is inverted or does not enclose its
// children's boxes or its triangles' float32 vertices, a leaf's references beyond the array, a
// reference in no leaf or several, a triangle index outside the triangles, a triangle referenced
// other than exactly once, a triangle record whose word 9 is not its index or whose words 10-11
// are not 0. At most kMaxBvhProblems are listed; a last entry then says more were left out.
// Empty for a sound image.
constexpr size_t kMaxBvhProblems = kMaxImageProblems;
std::vector<BvhProblem> validateBvh(const std::vector<uint32_t>& words);

// The validator's problems as one message: "<what> is not a sound BVH image:" then at most `shown`
// problems, one per line.
inline std::string describeBvhProblems(const std::string& what,
                                       const std::vector<BvhProblem>& problems, size_t shown = 10) {
  return describeImageProblems(what, "BVH", problems, shown);
}

}  // namespace rtu
