#pragma once
// Structural check of a BIH memory image (bih_image.h) before a traversal reads it, on the words
// alone, so an image from a file is checked as one just laid out. The walk from the root carries
// each node's interval box (the scene box narrowed by the clip planes on its path) and depth, and
// visits each node once.

#include <cstdint>
#include <string>
#include <vector>

#include "rtu/image_problems.h"

namespace rtu {

// Every problem found, in the order found (at most kMaxImageProblems, then an entry saying so):
//   header   not this format, a reserved word or flag set, a format validateFixedTriangleFormat
//   refuses,
//            a scene box beyond the grid, sections not where bihSections places them, a size
//            other than the header's (then nothing further is read);
//   nodes    a child outside the nodes or reached a second time, a node reached from no parent,
//            bit 2 or the bits above the index set, a pad word not 0, a node deeper than
//            kBihMaxDepth (the 32-entry stack), a leaf of count 0 (it would wrap the FSM's
//            counter), clip1 not 0 or its entries beyond the list;
//   list     an entry in no leaf or several, a triangle number outside the triangles;
//   records  a triangle in no leaf, r > 2, pp or pq beyond the grid, or its first vertex (pp, pq)
//            outside the interval box of a leaf that lists it.
std::vector<ImageProblem> validateBih(const std::vector<uint32_t>& words);

// "<what> is not a sound BIH image:" then at most `shown` problems, one per line.
inline std::string describeBihProblems(const std::string& what,
                                       const std::vector<ImageProblem>& problems,
                                       size_t shown = 10) {
  return describeImageProblems(what, "BIH", problems, shown);
}

}  // namespace rtu
