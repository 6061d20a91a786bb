#include "kinds/svo/svo_builder.h"

#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rtu {

std::string SvoStats::describe() const {
  return std::to_string(descriptors) + " descriptors, " + std::to_string(leaves) + " leaves, " +
         std::to_string(farPointers) + " far pointers, depth " + std::to_string(depth) + ", " +
         std::to_string(bytes()) + " bytes";
}

namespace {

// A built subtree before its descriptor is placed: the masks of its descriptor and everything
// stored below it, with pointers relative to the start of `below`.
struct Subtree {
  Occupancy occupancy = Occupancy::Empty;
  uint8_t valid = 0;
  uint8_t leaf = 0;
  std::vector<uint32_t> below;
};

class Builder {
 public:
  explicit Builder(const VoxelSource& source) : source_(source) {}

  Subtree build(const OctreeNode& node) {
    const Occupancy occupancy = source_.classify(node);
    if (occupancy != Occupancy::Mixed) return Subtree{occupancy, 0, 0, {}};
    if (node.level >= source_.depth())
      throw std::invalid_argument("voxel source answered 'mixed' for a voxel at level " +
                                  std::to_string(node.level));

    std::array<Subtree, 8> children;
    int full = 0;
    int empty = 0;
    for (int slot = 0; slot < 8; ++slot) {
      children[slot] = build(node.child(slot));
      full += children[slot].occupancy == Occupancy::Full;
      empty += children[slot].occupancy == Occupancy::Empty;
    }
    if (full == 8) return Subtree{Occupancy::Full, 0, 0, {}};
    if (empty == 8) return Subtree{Occupancy::Empty, 0, 0, {}};

    Subtree subtree{Occupancy::Mixed, 0, 0, {}};
    for (int slot = 0; slot < 8; ++slot) {
      if (children[slot].occupancy == Occupancy::Empty) continue;
      subtree.valid |= static_cast<uint8_t>(1u << slot);
      if (children[slot].occupancy == Occupancy::Full) {
        subtree.leaf |= static_cast<uint8_t>(1u << slot);
        ++stats_.leaves;
        stats_.depth = std::max(stats_.depth, node.level + 1);
      }
    }
    subtree.below = layOutBlock(children);
    return subtree;
  }

  // The root is a lone descriptor whose block follows it directly.
  SvoImage finish(Subtree root, uint32_t rootAddress) {
    if (root.occupancy == Occupancy::Full) {
      root.valid = root.leaf = 0xFF;
      stats_.leaves += 8;
      stats_.depth = std::max(stats_.depth, 1);
    }
    SvoImage image;
    image.root = rootAddress;
    image.words.assign(rootAddress, 0u);
    const uint32_t pointer = root.below.empty() ? 0 : 1;
    image.words.push_back(Descriptor::make(false, pointer, root.valid, root.leaf).word);
    ++stats_.descriptors;
    image.words.insert(image.words.end(), root.below.begin(), root.below.end());
    stats_.words = image.words.size();
    return image;
  }

  const SvoStats& stats() const { return stats_; }

 private:
  // The block of the mixed children's descriptors, its far words, then each child's `below`.
  std::vector<uint32_t> layOutBlock(std::array<Subtree, 8>& children) {
    std::vector<Subtree*> mixed;
    for (Subtree& child : children)
      if (child.occupancy == Occupancy::Mixed) mixed.push_back(&child);
    const size_t count = mixed.size();

    // Distance from descriptor i to the start of its child's `below`, given the far word count.
    auto distance = [&](size_t farWords, size_t i) {
      size_t offset = count + farWords;
      for (size_t j = 0; j < i; ++j) offset += mixed[j]->below.size();
      return offset - i;
    };
    // Far words lengthen the distances, which may call for more far words: iterate to the fixed
    // point (at most `count` rounds, as the set of far descriptors only grows).
    std::vector<bool> far(count, false);
    size_t farWords = 0;
    for (bool changed = true; changed;) {
      changed = false;
      for (size_t i = 0; i < count; ++i) {
        const bool needsFar =
            !mixed[i]->below.empty() && distance(farWords, i) > Descriptor::kMaxPointer;
        if (needsFar && !far[i]) {
          far[i] = true;
          ++farWords;
          changed = true;
        }
      }
    }

    size_t total = count + farWords;
    for (const Subtree* child : mixed) total += child->below.size();
    std::vector<uint32_t> block;
    block.reserve(total);
    std::vector<uint32_t> farValues;
    size_t farIndex = 0;
    for (size_t i = 0; i < count; ++i) {
      const Subtree& child = *mixed[i];
      uint32_t pointer = 0;
      if (!child.below.empty()) {
        if (far[i]) {
          pointer = static_cast<uint32_t>(count + farIndex++ - i);
          farValues.push_back(static_cast<uint32_t>(distance(farWords, i)));
        } else {
          pointer = static_cast<uint32_t>(distance(farWords, i));
        }
      }
      block.push_back(Descriptor::make(far[i], pointer, child.valid, child.leaf).word);
    }
    stats_.descriptors += count;
    stats_.farPointers += farWords;
    block.insert(block.end(), farValues.begin(), farValues.end());
    for (Subtree* child : mixed) {
      block.insert(block.end(), child->below.begin(), child->below.end());
      std::vector<uint32_t>().swap(child->below);  // release as we go: memory stays bounded
    }
    return block;
  }

  const VoxelSource& source_;
  SvoStats stats_;
};

}  // namespace

SvoBuild buildSvo(const VoxelSource& source, uint32_t rootAddress) {
  if (source.depth() < 1 || source.depth() > kMaxSvoDepth)
    throw std::invalid_argument("SVO depth must be 1 to " + std::to_string(kMaxSvoDepth) +
                                ", got " + std::to_string(source.depth()));
  Builder builder(source);
  Subtree root = builder.build(OctreeNode{});
  SvoImage image = builder.finish(std::move(root), rootAddress);
  return SvoBuild{std::move(image), builder.stats()};
}

}  // namespace rtu
