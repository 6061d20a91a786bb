#include "scene/scene_manager_timing.h"

#include <stdexcept>
#include <string>

namespace rtu {

const StatisticGroup<SceneManagerStatistics>& SceneManagerStatistics::declaration() {
  using S = SceneManagerStatistics;
  static const StatisticGroup<SceneManagerStatistics> group =
      StatisticGroup<SceneManagerStatistics>("the scene manager")
          .count(Statistic("rays", "rays", "rays the scene manager took"), &S::rays)
          .count(Statistic("jobs", "jobs",
                           "jobs it issued: one per instance a ray was traced against"),
                 &S::jobs)
          .derived(Statistic("jobs_per_ray", "jobs", "jobs per ray, 0 without rays"),
                   [](const S& s) {
                     return s.rays == 0 ? 0.0 : static_cast<double>(s.jobs) / s.rays;
                   })
          .histogram(Statistic("jobs_per_ray_histogram", "rays", "rays by their number of jobs")
                         .keyedByValue(),
                     &S::jobsPerRay)
          .count(Statistic("instances_culled", "instances",
                           "instances whose bounding sphere a ray missed"),
                 &S::culled)
          .count(Statistic("early_terminations", "rays",
                           "rays that ended with instances left to trace"),
                 &S::earlyTerminations)
          .count(Statistic("instances_skipped", "instances", "instances those rays did not trace"),
                 &S::skipped);
  return group;
}

void SceneManagerConfig::validate() const {
  if (raysInFlight < 1)
    throw std::invalid_argument("scene_manager.rays_in_flight must be at least 1, got " +
                                std::to_string(raysInFlight));
  if (jobsOutstanding < 1)
    throw std::invalid_argument("scene_manager.jobs_outstanding must be at least 1, got " +
                                std::to_string(jobsOutstanding));
  if (latency < 0)
    throw std::invalid_argument("scene_manager.latency must not be negative, got " +
                                std::to_string(latency));
}

}  // namespace rtu
