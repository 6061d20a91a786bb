#include "kinds/svo/svo_bounds.h"

#include <glm/common.hpp>

#include "kinds/svo/voxel_source.h"

namespace rtu {

namespace {

class BoundsWalk {
 public:
  explicit BoundsWalk(const SvoImage& image) : memory_(image.memory()) {}

  void visit(uint32_t address, const OctreeNode& node) {
    const Descriptor descriptor{memory_.read(address)};
    for (int slot = 0; slot < 8; ++slot) {
      if (!(descriptor.validMask() >> slot & 1)) continue;
      const OctreeNode child = node.child(slot);
      if (covered(child)) continue;
      if (descriptor.leafMask() >> slot & 1)
        include(child);
      else
        visit(childAddress(address, descriptor) + descriptor.childOffset(slot), child);
    }
  }

  const VoxelBounds& bounds() const { return bounds_; }

 private:
  // The child block's address, through the far word when the descriptor has one (as the core).
  uint32_t childAddress(uint32_t address, const Descriptor& descriptor) const {
    const uint32_t pointer = descriptor.childPointer();
    return address + (descriptor.far() ? memory_.read(address + pointer) : pointer);
  }

  // A node inside the box found so far cannot widen it: its subtree need not be walked.
  bool covered(const OctreeNode& node) const {
    return !bounds_.empty && glm::all(glm::greaterThanEqual(node.lower(), bounds_.lower)) &&
           glm::all(glm::lessThanEqual(node.upper(), bounds_.upper));
  }

  void include(const OctreeNode& node) {
    bounds_.lower = bounds_.empty ? node.lower() : glm::min(bounds_.lower, node.lower());
    bounds_.upper = bounds_.empty ? node.upper() : glm::max(bounds_.upper, node.upper());
    bounds_.empty = false;
  }

  WordMemory memory_;
  VoxelBounds bounds_;
};

}  // namespace

VoxelBounds solidVoxelBounds(const SvoImage& image) {
  BoundsWalk walk(image);
  walk.visit(image.root, OctreeNode{});
  return walk.bounds();
}

}  // namespace rtu
