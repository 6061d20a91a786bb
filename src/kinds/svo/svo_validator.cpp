#include "kinds/svo/svo_validator.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace rtu {

SvoFormatError::SvoFormatError(uint32_t address, const std::string& problem)
    : std::runtime_error("SVO word " + std::to_string(address) + ": " + problem),
      address_(address) {}

std::string describe(const SvoReport& report) {
  return std::to_string(report.descriptors) + " descriptors (" +
         std::to_string(report.sharedDescriptors) + " shared), " + std::to_string(report.leaves) +
         " leaves, " + std::to_string(report.farPointers) + " far pointers, depth " +
         std::to_string(report.depth) + ", " + std::to_string(report.words * 4) + " bytes";
}

namespace {

std::string hexByte(uint8_t value) {
  char text[5];
  std::snprintf(text, sizeof text, "0x%02X", value);
  return text;
}

// The descriptors of a descriptor's non-leaf children: `count` words from `first`.
struct Block {
  uint32_t first = 0;
  uint32_t count = 0;
};

// Depth-first walk with an explicit stack, so a deep chain in a corrupt image cannot overflow the
// call stack. A word is New until entered, OnPath while its subtree is walked (meeting it again
// then is a cycle) and Done after, when its heights are final and reused by every other parent.
class Validator {
 public:
  explicit Validator(const SvoImage& image)
      : image_(image),
        // Addresses are 32-bit: words beyond 2^32 cannot be named.
        size_(std::min<uint64_t>(image.words.size(), uint64_t{1} << 32)),
        state_(size_) {}

  // Walks the tree at `root`. Words a walk from another root finished are not entered again, so
  // any number of roots cost one pass over the image.
  void walk(uint32_t root) {
    if (root >= size_)
      throw SvoFormatError(root, "the root descriptor is outside the image of " +
                                     std::to_string(size_) + " words");
    if (state_[root].visit == Visit::Done) return;
    enter(root);
    while (!path_.empty()) {
      Frame& frame = path_.back();
      if (frame.next == frame.children.count) {
        leave();
      } else {
        const uint32_t parent = frame.address;
        visitChild(parent, frame.children.first + frame.next++);  // may grow path_
      }
    }
  }

  // The report of the one tree walked, at image_.root.
  SvoReport report(const SvoLimits& limits) {
    checkDepth(limits.maxDepth);
    report_.depth = static_cast<int>(state_[image_.root].leafHeight);
    report_.descriptorDepth = static_cast<int>(state_[image_.root].descriptorHeight);
    report_.words = image_.words.size();
    return report_;
  }

  int descriptorDepth(uint32_t root) const {
    return static_cast<int>(state_[root].descriptorHeight);
  }

 private:
  enum class Visit : uint8_t { New, OnPath, Done };

  struct WordState {
    Visit visit = Visit::New;
    uint8_t references = 0;         // child pointers naming this word, saturating at 2
    uint32_t reach = 0;             // levels below the descriptor down to its deepest valid child
    uint32_t leafHeight = 0;        // levels below it down to its deepest leaf, 0 without leaves
    uint32_t descriptorHeight = 0;  // levels below it down to its deepest descriptor
  };

  struct Frame {
    uint32_t address;
    Block children;
    uint32_t next;  // index in `children` of the next child to visit
  };

  Descriptor descriptorAt(uint32_t address) const { return Descriptor{image_.words[address]}; }

  std::string outside() const {
    return ", outside the image of " + std::to_string(size_) + " words";
  }

  void enter(uint32_t address) {
    const Descriptor descriptor = descriptorAt(address);
    checkSlots(address, descriptor);
    const Block children = childBlock(address);
    ++report_.descriptors;
    report_.leaves += static_cast<size_t>(__builtin_popcount(descriptor.leafMask()));
    if (descriptor.far() && children.count > 0) ++report_.farPointers;

    WordState& state = state_[address];
    state.visit = Visit::OnPath;
    state.reach = descriptor.validMask() != 0 ? 1 : 0;
    state.leafHeight = descriptor.leafMask() != 0 ? 1 : 0;
    path_.push_back(Frame{address, children, 0});
  }

  void visitChild(uint32_t parent, uint32_t child) {
    WordState& state = state_[child];
    if (state.references < 2 && ++state.references == 2) ++report_.sharedDescriptors;
    switch (state.visit) {
      case Visit::New: enter(child); break;
      case Visit::OnPath:
        throw SvoFormatError(child, "cycle: the descriptor is reachable from itself (through "
                                    "the child pointer of word " +
                                        std::to_string(parent) + ")");
      case Visit::Done: fold(parent, child); break;
    }
  }

  void leave() {
    const uint32_t address = path_.back().address;
    state_[address].visit = Visit::Done;
    path_.pop_back();
    if (!path_.empty()) fold(path_.back().address, address);
  }

  // Adds a finished child's heights to its parent's.
  void fold(uint32_t parent, uint32_t child) {
    WordState& into = state_[parent];
    const WordState& from = state_[child];
    into.reach = std::max(into.reach, from.reach + 1);
    if (from.leafHeight > 0) into.leafHeight = std::max(into.leafHeight, from.leafHeight + 1);
    into.descriptorHeight = std::max(into.descriptorHeight, from.descriptorHeight + 1);
  }

  static void checkSlots(uint32_t address, Descriptor descriptor) {
    const uint8_t invalidLeaves = descriptor.leafMask() & ~descriptor.validMask();
    if (invalidLeaves == 0) return;
    throw SvoFormatError(address, "slot " + std::to_string(__builtin_ctz(invalidLeaves)) +
                                      " is marked leaf but not valid (valid mask " +
                                      hexByte(descriptor.validMask()) + ", leaf mask " +
                                      hexByte(descriptor.leafMask()) + ")");
  }

  // Resolves the child pointer as the traversal core does, far word included.
  Block childBlock(uint32_t address) const {
    const Descriptor descriptor = descriptorAt(address);
    const auto count = static_cast<uint32_t>(__builtin_popcount(descriptor.nonLeafMask()));
    if (count == 0) return Block{};
    const uint32_t pointer = descriptor.childPointer();
    std::string via = "child pointer " + std::to_string(pointer);
    uint32_t offset = pointer;
    if (descriptor.far()) {
      const uint64_t farAddress = uint64_t{address} + pointer;
      if (farAddress >= size_)
        throw SvoFormatError(address, "far pointer " + std::to_string(pointer) +
                                          " names far word " + std::to_string(farAddress) +
                                          outside());
      offset = image_.words[farAddress];
      via = "far word " + std::to_string(farAddress) + " holds offset " + std::to_string(offset) +
            ", which";
    }
    const uint32_t first = address + offset;  // modulo 2^32, as the RTL adds
    const uint64_t last = uint64_t{first} + count - 1;
    if (last >= size_)
      throw SvoFormatError(address, via + " puts the " + std::to_string(count) +
                                        " non-leaf children at words " + std::to_string(first) +
                                        ".." + std::to_string(last) + outside());
    return Block{first, count};
  }

  // Follows the deepest path from the root to the descriptor whose children are too deep.
  void checkDepth(int limit) const {
    const auto maxDepth = static_cast<uint32_t>(limit);
    uint32_t address = image_.root;
    for (uint32_t level = 0; level + state_[address].reach > maxDepth; ++level) {
      if (level == maxDepth)
        throw SvoFormatError(address, "valid children at level " + std::to_string(level + 1) +
                                          ", deeper than the maximum depth " +
                                          std::to_string(maxDepth));
      const Block children = childBlock(address);
      const uint32_t reach = state_[address].reach;
      for (uint32_t i = 0; i < children.count; ++i) {
        if (state_[children.first + i].reach + 1 == reach) {
          address = children.first + i;
          break;
        }
      }
    }
  }

  const SvoImage& image_;
  const uint64_t size_;
  std::vector<WordState> state_;
  std::vector<Frame> path_;
  SvoReport report_;
};

}  // namespace

SvoReport validateSvo(const SvoImage& image, const SvoLimits& limits) {
  if (limits.maxDepth < 0)
    throw std::invalid_argument("SVO depth limit must not be negative, got " +
                                std::to_string(limits.maxDepth));
  Validator validator(image);
  validator.walk(image.root);
  return validator.report(limits);
}

std::vector<int> descriptorDepths(const SvoImage& image, const std::vector<uint32_t>& roots) {
  Validator validator(image);
  std::vector<int> depths;
  depths.reserve(roots.size());
  for (uint32_t root : roots) {
    validator.walk(root);
    depths.push_back(validator.descriptorDepth(root));
  }
  return depths;
}

}  // namespace rtu
