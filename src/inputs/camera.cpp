#include "inputs/camera.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "base/work_phase.h"

namespace rtu {

namespace {

std::string vectorText(const glm::dvec3& v) {
  std::ostringstream text;
  text << v.x << "," << v.y << "," << v.z;
  return text.str();
}

}  // namespace

void Camera::validate() const {
  if (width < 1 || height < 1)
    throw std::invalid_argument("image size must be at least 1x1, got " + std::to_string(width) +
                                "x" + std::to_string(height));
  if (pixelCount() > TValueRecord::kMaxId + 1)
    throw std::invalid_argument("image has " + std::to_string(pixelCount()) +
                                " pixels; job ids have 28 bits, so at most 268435456");
  if (!(verticalFovDegrees > 0.0 && verticalFovDegrees < 180.0))
    throw std::invalid_argument("camera.fov must be between 0 and 180 degrees");
  // Each setting is named: a camera that makes no rays used to surface as "ray origin and
  // direction must be finite numbers", or as an empty frame (up = 0,0,0).
  const glm::dvec3 forward = lookAt - position;
  const double upLength = glm::length(up), forwardLength = glm::length(forward);
  if (!std::isfinite(forwardLength))
    throw std::invalid_argument("camera.position and camera.look_at are too far apart (" +
                                vectorText(position) + " and " + vectorText(lookAt) + ")");
  if (forwardLength == 0.0)
    throw std::invalid_argument("camera.position and camera.look_at coincide (" +
                                vectorText(position) + ")");
  if (!(upLength > 0.0) || !std::isfinite(upLength))
    throw std::invalid_argument("camera.up must be a non-zero vector, got " + vectorText(up));
  if (!(glm::length(glm::cross(forward, up)) > 1e-12 * forwardLength * upLength))
    throw std::invalid_argument("camera.up (" + vectorText(up) +
                                ") is parallel to the view direction from camera.position to "
                                "camera.look_at");
}

Ray Camera::primaryRay(int x, int y) const {
  const glm::dvec3 forward = glm::normalize(lookAt - position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
  const glm::dvec3 trueUp = glm::cross(right, forward);
  const double halfHeight = std::tan(verticalFovDegrees * M_PI / 360.0);
  const double halfWidth = halfHeight * width / height;
  const double u = ((x + 0.5) / width * 2.0 - 1.0) * halfWidth;
  const double v = (1.0 - (y + 0.5) / height * 2.0) * halfHeight;
  return Ray{position, forward + u * right + v * trueUp};
}

Ray Camera::pixelRay(uint64_t index) const {
  const uint64_t w = static_cast<uint64_t>(width);
  return primaryRay(static_cast<int>(index % w), static_cast<int>(index / w));
}

std::vector<Ray> frameRays(const Camera& camera) {
  camera.validate();
  const WorkPhase phase("making the rays of a " + std::to_string(camera.width) + "x" +
                        std::to_string(camera.height) + " frame");
  std::vector<Ray> rays;
  rays.reserve(camera.pixelCount());
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x) rays.push_back(camera.primaryRay(x, y));
  return rays;
}

std::vector<TValueRecord> makeFrameJobs(const Camera& camera, uint32_t root, double epsilon) {
  const std::vector<Ray> rays = frameRays(camera);
  std::vector<TValueRecord> jobs;
  jobs.reserve(rays.size());
  for (size_t id = 0; id < rays.size(); ++id)
    jobs.push_back(makeTValueRecord(static_cast<uint32_t>(id), rays[id], root, epsilon));
  return jobs;
}

std::vector<RayRecord> makeFrameRayRecords(const Camera& camera, uint32_t modelAddress) {
  const std::vector<Ray> rays = frameRays(camera);
  std::vector<RayRecord> records;
  records.reserve(rays.size());
  for (size_t id = 0; id < rays.size(); ++id)
    records.push_back(makeRayRecord(static_cast<uint32_t>(id), rays[id], modelAddress));
  return records;
}

glm::dvec3 parseVector(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  glm::dvec3 v;
  char comma1 = 0, comma2 = 0;
  if (!(in >> v.x >> comma1 >> v.y >> comma2 >> v.z) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof() || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw std::invalid_argument(what + " must be three numbers 'x,y,z', got '" + text + "'");
  return v;
}

}  // namespace rtu
