#pragma once
// Structural check of an SVO memory image (thesis section 4.2, appendix C.4) before a model
// traverses it. The walk starts at the root descriptor and follows every child pointer, near or
// far, the way the traversal core resolves them; each word is visited once, so shared subtrees
// (DAGs) cost nothing extra and any image, however corrupt, is checked in linear time.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinds/svo/svo_image.h"

namespace rtu {

struct SvoLimits {
  int maxDepth = 12;  // deepest level a valid child may sit at; the root cube is level 0
};

// Counts are over the stored image: a descriptor shared by several parents counts once, and so
// do its leaves. For an image written by buildSvo they equal its SvoStats.
struct SvoReport {
  size_t descriptors = 0;        // reachable descriptors, the root included
  size_t leaves = 0;             // leaf-mask bits of those descriptors
  size_t farPointers = 0;        // descriptors whose children are reached through a far word
  size_t sharedDescriptors = 0;  // descriptors named by more than one child pointer
  int depth = 0;                 // deepest level holding a leaf; the root's leaf children are 1
  // Deepest level holding a descriptor, leafless or not: the traversal stack frames the tree
  // needs, one per descent (a chain of leafless descriptors needs them too).
  int descriptorDepth = 0;
  size_t words = 0;  // size of the image
};

class SvoFormatError : public std::runtime_error {
 public:
  SvoFormatError(uint32_t address, const std::string& problem);
  uint32_t address() const { return address_; }  // the word the problem was found at

 private:
  uint32_t address_;
};

// Throws SvoFormatError for: a root outside the image, a child block or far word outside it, a
// leaf bit on an invalid slot, a descriptor reachable from itself, or a valid child deeper than
// limits.maxDepth.
SvoReport validateSvo(const SvoImage& image, const SvoLimits& limits = {});

// The descriptorDepth of the tree at each root, with the checks of validateSvo but no depth limit,
// in one pass over the image however many roots share it.
std::vector<int> descriptorDepths(const SvoImage& image, const std::vector<uint32_t>& roots);

std::string describe(const SvoReport& report);  // one line for reports

}  // namespace rtu
