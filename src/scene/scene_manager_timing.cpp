#include "scene/scene_manager_timing.h"

#include <stdexcept>
#include <string>

namespace rtu {

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
