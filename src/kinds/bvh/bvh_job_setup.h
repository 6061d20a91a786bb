#pragma once
// The job manager's set-up of a world-space ray record for the BVH core (issue 28), through the
// model header and image header every triangle kind reads (rtu/ray_models.h): word 15 of the
// model header is the word address of the model's BVH image (its 16-word header first,
// bvh_image.h; the sections' bases are relative to it). The `rayStages` of every ray are the move
// into the model's space (rtu/model_transform.h, steps 1-3) and the reciprocal direction of its
// slab tests (bvh_ray.h). The model-space ray keeps the parameter t of the world-space one, over
// [0, infinity) for a line (the thesis' rays).
//
// The record's span (rtu/ray_span.h): a ray with one leaves a surface, so its float32 hit point's
// rounding must not find that surface again: it is traced from t = kBvhSpanTMin on (the float
// epsilon of a renderer's secondary rays, in units of the direction: 2^-16 of a shadow ray's
// length, 2^-16 world units for a unit direction, some hundred float32 steps of coordinates
// near 1); an any-hit ray ends at t = 1 and at its first hit (bvh_traversal.h).
//
// An image whose header word 11 is not 0 is a two-level BVH's top level (two_level_image.h): the
// word is its instance records' address relative to the image, and the jobs are two-level.

#include <cstdint>

#include "kinds/bvh/bvh_traversal.h"
#include "rtu/core_kind.h"
#include "rtu/job_manager_timing.h"
#include "rtu/model_header.h"
#include "rtu/ray_models.h"
#include "rtu/ray_record.h"
#include "rtu/word_memory.h"

namespace rtu {

inline constexpr float kBvhSpanTMin = 0x1p-16f;

class BvhJobSetup {
 public:
  BvhJobSetup(WordMemory memory, const JobManagerTiming& timing)
      : memory_(memory), models_(timing) {}

  // Throws std::runtime_error naming the address for a model header that is not valid, or an
  // image that lies outside the memory, is not on a multiple of 4 words or is not a BVH's.
  JobSetUp<BvhJob> setUp(const RayRecord& record);

 private:
  struct Model {
    ModelTransform transform;
    BvhSections image;       // word addresses in the memory
    uint32_t instances = 0;  // a two-level image's instance records (two_level_image.h), or 0
  };
  Model readModel(uint32_t address) const;

  WordMemory memory_;
  RayModels<Model> models_;
};

}  // namespace rtu
