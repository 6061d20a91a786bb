#pragma once
// The walk of a two-level BVH's top level for one world-space ray (two_level.h): it hands out the
// instances whose world boxes the ray enters, one at a time, as the scene manager hands out one
// job per model instance (scene/scene_manager.h), and is told the nearest hit so far before each.
// Its rule is the mesh traversal's (bvh_traversal.h, S3 §3.2.6 L675-681): both child boxes are
// tested at the parent by the float32 slab test against [tMin, tBest] (bvh_ray.h); the nearer hit
// child, the left on equal entries, goes on and the other is pushed; a popped entry beginning
// beyond the nearest hit is skipped; a leaf's instances come in reference order. Untimed: it reads
// the top level's image through BvhImageView; what the timed issue makes of it (a state machine of
// its own or the host's walk) is docs/triangles.md's "Two-level BVH".

#include <cstdint>
#include <optional>

#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_ray.h"
#include "rtu/traversal_stack.h"

namespace rtu {

// What one ray's walk counted.
struct TopLevelCounts {
  uint32_t nodes = 0;  // node records read
  uint32_t boxTests = 0;
  uint32_t pushes = 0, pops = 0;
  uint32_t dropped = 0;    // stack entries lost to a push onto a full stack
  uint32_t instances = 0;  // instances handed out: mesh traversals
};

class TopLevelWalk {
 public:
  explicit TopLevelWalk(int stackDepth) : stack_(stackDepth) {}

  // Starts the walk of `ray` (world space) over `image`, which must outlive it; tests the root.
  void start(const BvhImage& image, const BvhRay& ray);
  // The next instance whose box the ray enters no later than `tBest`, the nearest hit so far (or
  // the ray's tMax); none when the walk is done.
  std::optional<uint32_t> next(float tBest);

  TopLevelCounts counts() const;

 private:
  struct Entry {
    BvhNode node;
    float tEntry = 0;
  };

  BvhNode readNode(uint32_t index);
  BoxHit test(const BvhNode& node);
  // Goes into `node`: a leaf's instances become pending, an inner node's hit children decide
  // where to go next.
  void enter(const BvhNode& node);
  // The next node to go into, from the one chosen last or the stack; false when none is left.
  bool advance();

  RingStack<Entry> stack_;
  std::optional<BvhImageView> view_;
  BvhRay ray_;
  float tBest_ = 0;
  std::optional<BvhNode> chosen_;  // the hit child to go into next
  uint32_t nextRef_ = 0, refsLeft_ = 0;
  TopLevelCounts counts_;
};

}  // namespace rtu
