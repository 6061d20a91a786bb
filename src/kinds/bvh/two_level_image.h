#pragma once
// A two-level BVH (two_level.h) as one memory image the BVH core traverses (bvh_traversal.h,
// "Two levels"; docs/triangles.md, "Two-level BVH in the core"). Layout, word addresses:
//   mesh images   each mesh's BVH image (bvh_image.h) in turn, each on a multiple of 4 words:
//                 written once and kept from frame to frame
//   top level     the frame's top-level image (header, nodes, references naming instances; no
//                 triangles), its sections made absolute
//   instances     kBvhInstanceWords per instance (bvh_traversal.h): the inverse placement, the
//                 primitive base, the mesh's sections
//   world header  a model header (rtu/model_header.h) with the identity placement whose root is the
//                 top level's image: what a ray record names, so the job set-up
//                 (bvh_job_setup.h) makes two-level jobs of world-space rays
// The top level's header word 11 holds the instance records' address relative to the image
// (0 in a one-level image): the job set-up's sign of two levels.
//
// An instance's primitive base is the count of the triangles of the instances before it, so a hit
// names its triangle in the frame's instances concatenated in order, as the scene file's frame
// flattened into one world mesh does (explore/scene_mesh.h).

#include <cstdint>
#include <vector>

#include "kinds/bvh/bvh_traversal.h"
#include "kinds/bvh/two_level.h"
#include "rtu/word_memory.h"

namespace rtu {

constexpr uint32_t kBvhInstanceBaseWord = 11;  // the top-level header's word

class TwoLevelImage {
 public:
  // The meshes' images laid out once.
  explicit TwoLevelImage(const TwoLevelBvh& bvh);

  // Rewrites the top level, instance records and world header after the mesh images from the
  // frame's top level (bvh.topLevel(), after place()). Throws BvhCapacityError when the words
  // exceed 2^32 - 1.
  void writeFrame(const TwoLevelBvh& bvh);

  WordMemory memory() const { return WordMemory(words_); }
  const std::vector<uint32_t>& words() const { return words_; }
  // The frame's job for a world ray (after writeFrame).
  BvhJob job(const BvhRay& ray) const { return BvhJob{ray, top_, false, instances_}; }
  // The world header's address: a ray record's model address (after writeFrame).
  uint32_t worldHeader() const { return worldHeader_; }

 private:
  std::vector<uint32_t> words_;
  size_t meshWords_ = 0;
  std::vector<BvhSections> meshes_;  // absolute
  std::vector<uint32_t> meshTriangles_;
  BvhSections top_;
  uint32_t instances_ = 0, worldHeader_ = 0;
};

}  // namespace rtu
