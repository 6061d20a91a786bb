#pragma once
// `rtusim render --architecture raypipe` (issue 29): seed 001's ray pipe renders one frame. The
// scene's triangles are built into the Tray Racer's k-d tree and scene file (explore/
// accel_build.h, `accel.index` choosing the file's narrow or wide form) and traced as the
// hardware reads that file; the primary ray generator's rays (raypipe/primary_rays.h) from the
// camera registers (raypipe.camera.*, or rtusim's camera converted) at raypipe.level or
// width x height run through the golden k-d traversal (raypipe/raypipe_golden.h). Or the scene is
// a file built before (--accel-file): a k-d image (`build --accel kdtree --out x.kd`) or the
// seed's scene file (`--trayracer-scene`, R1's SCENES/*.scene; narrow unless --index wide). Its
// outputs:
// the report, the simple shader's image (--image), a Lambert-shaded, depth or cost image, and
// --results-csv in issue order. With --model ca (the default) the frame also runs on the pipe's
// timed model (sim/raypipe/raypipe_timed.h), whose results must equal the golden frame's: the
// report gains the frame's cycles and rate, the busiest units, stalls and FIFOs, and the CSV each
// ray's issue and exit cycles. --model lt is refused before any work.

#include <iosfwd>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/frame_image_writer.h"
#include "app/frame_images.h"
#include "app/output_paths.h"
#include "app/run_outputs.h"
#include "config/configuration.h"
#include "raypipe/primary_rays.h"
#include "raypipe/raypipe_camera.h"
#include "raypipe/raypipe_golden.h"

namespace rtu {

// The options only the ray pipe takes: its scene as a built file, and the outputs it writes.
struct RaypipeRenderOptions {
  std::string accelFile;  // a k-d image (.kd) or the seed's scene file instead of a build
  std::string resultsCsv, shadedImage;

  std::vector<NamedPath> paths() const {
    return {{"--results-csv", resultsCsv}, {"--shaded-image", shadedImage}};
  }
};

void addRaypipeRenderOptions(CLI::App& command, RaypipeRenderOptions& options);

// Throws std::invalid_argument naming an option given for the RTU, which only the pipe takes.
void checkRaypipeOnly(const RaypipeRenderOptions& options);

// Throws std::invalid_argument for --model lt: the pipe has golden and its timed model only.
void checkRaypipeModel(ModelKind model);

// Renders the frame `configuration` describes on the ray pipe's golden model (and, with --model
// ca, its timed model) and writes the outputs asked for: --stats, the timed frame's statistics
// (raypipe/raypipe_statistics.h) as a run's JSON; --trace and --timeline (app/raypipe_trace.h);
// the report goes to `out`.
void renderRaypipe(const Configuration& configuration, const FrameImagePaths& images,
                   const RaypipeRenderOptions& options, const RunOutputs& outputs,
                   std::ostream& out);

// The golden frame as rtusim's images take it: t in world units (hardware space only swaps axes),
// the hit triangle's index and normal (none without normals), the golden traversal's states as
// the cost.
RenderedFrame raypipeRenderedFrame(const RaypipeGoldenFrame& frame,
                                   const std::vector<PrimaryRay>& rays,
                                   const std::vector<glm::dvec3>& normals,
                                   const RaypipeCamera& registers, PrgFrameSize size);

}  // namespace rtu
