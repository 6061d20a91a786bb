#pragma once
// Seed 003's two-level object BVH (S3 §3.2.1 p.26 L573-584; §1.4.2 p.15 L388-390): each mesh is
// built once, in its own space, and kept as its memory image; an instance places a mesh in the
// world by a rigid placement with scale (rtu/model_transform.h); the top level is a BVH over the
// instances' world boxes, rebuilt per frame from the new placements while the mesh images stay.
// At a top-level leaf the world ray moves into the mesh's space by the inverse placement
// (`toModelSpace`, the SVO job set-up's steps 1-3) and the mesh's own BVH is traced there
// (two_level_traversal.h).
//
// An instance's world box is its mesh image's root box (float32, rounded outward, so it encloses
// the float32 triangles) with its 8 corners placed into the world in double, p = R (S c) + T, and
// re-boxed. The seed does not name the top level's builder (plan reading, issue 27 §1.1): the
// meshes' binned builder over the instance boxes (each box's centre its centroid) with leaves of
// one instance, so that a leaf needs one transform; the builder and leaf size are settings.
//
// Images: the top level is laid out as a BVH image (bvh_image.h) without triangles, its
// references naming instances; the instances' float32 transforms are the host's records beside it.

#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/triangle_mesh.h"
#include "kinds/bvh/build_tree.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_traversal.h"
#include "rtu/model_transform.h"

namespace rtu {

// A mesh's BVH as the two-level structure keeps it: the image and where its sections start, and
// the image's root box (what an instance's world box is made from).
struct MeshBvh {
  BvhImage image;
  BvhSections sections;
  Aabb<float> rootBox;
};

// The image of `tree` over `mesh` (any builder's tree), with its sections and root box.
MeshBvh meshBvh(const BuildTree& tree, const TriangleMesh& mesh);
// A built image's sections and root box (throws std::out_of_range as BvhImageView).
MeshBvh meshBvh(BvhImage image);

struct BvhInstance {
  uint32_t mesh = 0;  // index into the two-level BVH's meshes
  ModelPlacement placement;
};

enum class TopLevelBuilder { Binned, Langr };

struct TopLevelConfig {
  TopLevelBuilder builder = TopLevelBuilder::Binned;
  uint32_t leafSize = 1;  // instances per leaf at most (langr: its leaf threshold)
};

// `box`'s 8 corners placed by `placement` in double (p = R (S c) + T), re-boxed.
Aabb<double> placedBox(const Aabb<float>& box, const ModelPlacement& placement);

// One frame's top level.
struct TopLevel {
  std::vector<BvhInstance> instances;
  std::vector<ModelTransform> transforms;  // each instance's inverse, float32
  std::vector<Aabb<double>> worldBoxes;    // each instance's, as placedBox
  BuildTree tree;                          // over worldBoxes: references are instance indices
  BvhImage image;                          // the tree laid out, no triangles
  BvhSections sections;
};

class TwoLevelBvh {
 public:
  // Throws std::invalid_argument for no mesh or a leaf size of 0.
  explicit TwoLevelBvh(std::vector<MeshBvh> meshes, const TopLevelConfig& config = {});

  // A frame: the top level rebuilt over `instances`; the mesh images are kept as they are. Throws
  // std::invalid_argument for no instance, a mesh index out of range or a placement
  // makeModelTransform refuses (naming the instance).
  void place(std::vector<BvhInstance> instances);

  const std::vector<MeshBvh>& meshes() const { return *meshes_; }
  // Empty (no instances) until the first place().
  const TopLevel& topLevel() const { return topLevel_; }

 private:
  BuildTree buildTopLevel(const std::vector<Aabb<double>>& worldBoxes) const;

  // Read only, so copies share them (a thread's copy places its own frames: animate --threads).
  std::shared_ptr<const std::vector<MeshBvh>> meshes_;
  TopLevelConfig config_;
  TopLevel topLevel_;
};

}  // namespace rtu
