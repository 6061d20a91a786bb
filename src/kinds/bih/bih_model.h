#pragma once
// A BIH image in memory as a model the RTU traces world-space rays against (bih_job_setup.h). A
// BIH's model space is its grid (grid.h): the model header (rtu/model_header.h) maps the world
// onto the grid's units, the scene box's lower corner at 0, so that the job manager's float32
// move into the model's space (rtu/model_transform.h) leaves the set-up only the clip to the
// image's box [0, upper] and the rounding to grid integers (S4 §2.1.2 L287).

#include <cstdint>
#include <vector>

#include "kinds/bih/grid.h"
#include "rtu/model_header.h"

namespace rtu {

// The placement of `grid`'s units for a mesh placed by `placement`: a mesh point p sits on the
// grid at (p - lower) scale, so p_world = R (S / scale · p_grid) + R (S lower) + T.
ModelPlacement gridPlacement(const SceneGrid& grid, const ModelPlacement& placement);

// Appends to `words` (a BIH image on `grid`, its header at word 0) a model header for the mesh
// placed by `placement` and returns the header's word address (the old size). Throws as
// makeModelHeader.
uint32_t appendBihModelHeader(std::vector<uint32_t>& words, const SceneGrid& grid,
                              const ModelPlacement& placement);

}  // namespace rtu
