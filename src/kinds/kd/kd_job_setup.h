#pragma once
// The job manager's set-up of a world-space ray record for the k-d core (issue 28), through the
// model header and image header every triangle kind reads (rtu/ray_models.h): word 15 of the
// model header is the word address of the k-d image (kd_image.h, its 16-word header first; the
// sections' bases count from it, each a multiple of 4 words). The `rayStages` of every ray are
// the move into the model's space (rtu/model_transform.h, float32) and the swap of x and y into
// the seed's hardware space (reading K4), in which the image's splits, matrices and scene box
// lie; the scene box goes into the core's SINT registers with the job. The model-space ray keeps
// the parameter t of the world-space one.

#include <cstdint>

#include "kinds/kd/kd_traversal.h"
#include "rtu/core_kind.h"
#include "rtu/job_manager_timing.h"
#include "rtu/ray_models.h"
#include "rtu/ray_record.h"
#include "rtu/word_memory.h"

namespace rtu {

class KdJobSetup {
 public:
  KdJobSetup(WordMemory memory, const JobManagerTiming& timing)
      : memory_(memory), models_(timing) {}

  // Throws std::runtime_error naming the address for a model header that is not valid, or an
  // image that lies outside the memory, is not on a multiple of 4 words or is not a k-d image.
  JobSetUp<KdJob> setUp(const RayRecord& record);

 private:
  struct Model {
    ModelTransform transform;
    KdSections image;  // word addresses in the memory
  };
  Model readModel(uint32_t address) const;

  WordMemory memory_;
  RayModels<Model> models_;
};

}  // namespace rtu
