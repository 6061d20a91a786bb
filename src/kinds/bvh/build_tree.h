#pragma once
// The common output of every BVH builder (langr now; binned, sweep and lbvh later), in double:
// the "verbose" tree that bvh_image.h lays out as words. Building in double and quantising
// afterwards keeps one layout function for every builder (docs/triangles.md).

#include <cstdint>
#include <vector>

#include "geometry/aabb.h"

namespace rtu {

struct BuildNode {
  Aabb<double> box;  // encloses the node's triangles
  // The node's triangles are refs[first, first + count): a leaf's own, an inner node's those of
  // its subtree (every builder here partitions the reference array top down).
  uint32_t first = 0;
  uint32_t count = 0;
  // An inner node's children, indices into BuildTree::nodes; 0 in a leaf, since the root (node 0)
  // is nobody's child.
  uint32_t left = 0;
  uint32_t right = 0;

  bool leaf() const { return left == 0; }
};

struct BuildTree {
  std::vector<BuildNode> nodes;  // nodes[0] is the root
  std::vector<uint32_t> refs;    // triangle reference array: indices into the mesh's triangles
};

}  // namespace rtu
