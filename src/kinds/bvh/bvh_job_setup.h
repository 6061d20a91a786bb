#pragma once
// The job manager's set-up of a world-space ray record for the BVH core (issue 28): the record's
// model address names a model header (rtu/model_header.h), whose word 15 is the word address of
// the model's BVH image (its 16-word header first, bvh_image.h; the sections' bases are relative
// to it). The first ray against a model reads both headers, 16 words each at one word a cycle
// (2 x headerFetchCycles, in which no record is accepted), and keeps them for the rest of the
// run; every ray then goes through `rayStages` more than a t-value record: the move into the
// model's space (rtu/model_transform.h, steps 1-3) and the reciprocal direction of its slab
// tests (bvh_ray.h). The model-space ray keeps the parameter t of the world-space one, over
// [0, infinity).

#include <cstdint>
#include <map>

#include "kinds/bvh/bvh_traversal.h"
#include "rtu/core_kind.h"
#include "rtu/job_manager_timing.h"
#include "rtu/model_header.h"
#include "rtu/ray_record.h"
#include "rtu/word_memory.h"

namespace rtu {

class BvhJobSetup {
 public:
  BvhJobSetup(WordMemory memory, const JobManagerTiming& timing)
      : memory_(memory), timing_(timing) {}

  // Throws std::runtime_error naming the address for a model header that is not valid, or an
  // image that lies outside the memory, is not on a multiple of 4 words or is not a BVH's.
  JobSetUp<BvhJob> setUp(const RayRecord& record);

 private:
  struct Model {
    ModelTransform transform;
    BvhSections image;  // word addresses in the memory
  };
  Model readModel(uint32_t address) const;

  WordMemory memory_;
  JobManagerTiming timing_;
  std::map<uint32_t, Model> models_;  // by model address
};

}  // namespace rtu
