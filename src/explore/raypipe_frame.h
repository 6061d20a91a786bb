#pragma once
// A frame of seed 001's ray pipe (issue 29) as every command that runs one takes it (render, the
// rows of fps and sweep, fidelity): its scene as the pipe reads it, the primary ray generator's
// rays at raypipe.level or width x height from the camera registers, and the frame on the timed
// model (sim/raypipe/raypipe_timed.h) with the writer the settings give.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "config/run_config.h"
#include "raypipe/primary_rays.h"
#include "raypipe/raypipe_run.h"
#include "trace/cycle_trace.h"

namespace rtu {

// The scene as the pipe reads it: the memory image of its Tray Racer scene file and, for the
// shaded image, each triangle's normal in world space (none from a k-d image).
struct RaypipeScene {
  std::string name, description;
  std::vector<uint32_t> image;
  std::vector<glm::dvec3> normals;
  std::vector<std::string> warnings;  // capacities beyond the final build's BRAMs
};

// The run's triangles built by the seed's builder into its scene file (narrow, or wide with
// accel.index = wide) and read back as the hardware loads it; or, with `sceneFile`, a file built
// before: a k-d image (its magic first) or the seed's scene file. Throws std::runtime_error naming
// a file that is not a sound k-d scene.
RaypipeScene loadRaypipeScene(const RunConfig& settings, const std::string& sceneFile = "");

// raypipe.level's size, or width x height.
PrgFrameSize raypipeFrameSize(const RunConfig& settings);

// The PRG's rays of the frame, in issue order, from the camera registers.
std::vector<PrimaryRay> raypipeFrameRays(const RunConfig& settings);

// The frame on the timed model: `rays` through the pipe of settings.raypipe over `image`, the
// SRAM writer as raypipe.vga_window and raypipe.vga_phase say. Throws std::invalid_argument for
// settings the model does not take (raypipe/raypipe_config.h's validate, and the model's own).
// With `trace`, the run's trace goes to it (sim/raypipe/pipe_trace.h).
RaypipeCycleRun runRaypipeFrame(const RaypipeConfig& config, const std::vector<uint32_t>& image,
                                const std::vector<PrimaryRay>& rays, CycleTrace* trace = nullptr);

// The per-cycle reference (reference/raypipe_cycles.h) on the same frame, for fidelity.
RaypipeCycleRun runRaypipeReferenceFrame(const RaypipeConfig& config,
                                         const std::vector<uint32_t>& image,
                                         const std::vector<PrimaryRay>& rays);

}  // namespace rtu
