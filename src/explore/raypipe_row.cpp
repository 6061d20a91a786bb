#include "explore/raypipe_row.h"

#include <stdexcept>

#include "config/run_json.h"
#include "explore/raypipe_frame.h"
#include "raypipe/raypipe_statistics.h"
#include "run/statistics_output.h"
#include "sim/raypipe/raypipe_timed.h"

namespace rtu {

void checkRaypipeFrameRuns(const RunConfig& settings) {
  settings.camera.validate();
  checkRaypipeTimedTakes(settings.raypipe);
  if (recordedWorkload(settings))
    throw std::invalid_argument("jobs, rays: the ray pipe traces its primary ray generator's "
                                "frame, not a recorded workload");
}

void validateRaypipeRow(const RunConfig& settings) {
  checkRaypipeFrameRuns(settings);
  if (settings.model != ModelKind::CycleAccurate)
    throw std::invalid_argument(std::string("model = ") + toString(settings.model) +
                                ": the ray pipe's rows run its timed model (model = ca); golden "
                                "has no cycles and the pipe has no loosely-timed form");
  if (settings.sample.enabled())
    throw std::invalid_argument(
        "sample.fraction: the ray pipe's timed model is exact and costs per ray; it has no "
        "sampled mode");
}

nlohmann::ordered_json runRaypipeRow(const Configuration& configuration, const FrameScene& scene) {
  const RunConfig& settings = configuration.values();
  validateRaypipeRow(settings);
  if (scene.core != kRaypipeSceneCore)
    throw std::invalid_argument("a scene built for the " + scene.core +
                                " core cannot run on the ray pipe");
  const RaypipeCycleRun run =
      runRaypipeFrame(settings.raypipe, scene.words, raypipeFrameRays(settings));
  nlohmann::ordered_json row = {{"status", "ok"}, {"error", ""}};
  row.update(runJson(statisticsJson(RaypipeStatistics::of(run, settings.raypipe)), configuration));
  return row;
}

}  // namespace rtu
