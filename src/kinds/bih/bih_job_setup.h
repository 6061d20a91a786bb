#pragma once
// The job manager's set-up of a world-space ray record for the BIH core (issue 28), through the
// model header and image header every triangle kind reads (rtu/ray_models.h): word 15 of the
// model header is the word address of the BIH image (bih_image.h, its 16-word header first; the
// sections' bases count from it, a multiple of 4 words). The model header maps the world onto
// the image's grid (bih_model.h), so the `rayStages` of every ray are the move into the model's
// space (rtu/model_transform.h, float32) and seed 004's conversion (S4 §2.1.2 L287, grid.h):
// the ray clipped, in double, to the image's scene box [0, upper] (header words 11-13), then its
// origin rounded to grid integers, its direction to m-bit codes and its inverse direction to
// m + C bits in the image's formats (header word 14). A ray that misses the box is a job that
// ends in AABB. The grid ray keeps where the world ray entered the box, so a grid t maps back
// to the world ray's parameter (GridRay::worldT).
//
// The record's span (rtu/ray_span.h): the clip already starts every ray at t >= 0 (ahead), and
// the C99 kernel takes hits at t > 0 only; an any-hit ray's segment ends at world t = 1, so its
// job carries that end as a grid t (BihJob::tLimit). A ray leaving a surface is moved off it by
// its spawner, by seed 004's ±2 grid units (inputs/secondary_rays.h), not here: the job manager
// knows no normal.

#include <cstdint>

#include "kinds/bih/bih_traversal.h"
#include "kinds/bih/grid.h"
#include "rtu/core_kind.h"
#include "rtu/job_manager_timing.h"
#include "rtu/model_transform.h"
#include "rtu/ray_models.h"
#include "rtu/ray_record.h"
#include "rtu/word_memory.h"

namespace rtu {

class BihJobSetup {
 public:
  BihJobSetup(WordMemory memory, const JobManagerTiming& timing)
      : memory_(memory), models_(timing) {}

  // Throws std::runtime_error naming the address for a model header that is not valid, or an
  // image that lies outside the memory, is not on a multiple of 4 words, is not a BIH's, or whose
  // formats or scene box cannot be a grid's.
  JobSetUp<BihJob> setUp(const RayRecord& record);

 private:
  struct Model {
    ModelTransform transform;
    BihScene scene;  // word addresses in the memory
    SceneGrid grid;  // the image's box [0, upper] in grid units, in its formats
  };
  Model readModel(uint32_t address) const;

  WordMemory memory_;
  RayModels<Model> models_;
};

}  // namespace rtu
