#pragma once
// A pinhole camera producing one primary ray per pixel, and the job stream the thesis driver
// would send for a frame (appendix F) or the frame's ray records: job id = x + y * width, row 0
// at the top.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "kinds/svo/ray_setup.h"
#include "kinds/svo/ray_transform.h"
#include "kinds/svo/thesis_records.h"

namespace rtu {

struct Camera {
  glm::dvec3 position{-1.9, 1.3, -2.6};
  glm::dvec3 lookAt{0.0, 0.0, 0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double verticalFovDegrees = 50.0;
  int width = 320;
  int height = 180;

  // Throws std::invalid_argument for an empty or oversized image (ids have 28 bits), a field of
  // view outside (0, 180) degrees, or a view direction parallel to `up`.
  void validate() const;

  // Through the centre of pixel (x, y).
  Ray primaryRay(int x, int y) const;
  // Pixel `index`'s, row by row from the top (index = x + y * width), as frameRays orders them.
  Ray pixelRay(uint64_t index) const;
  size_t pixelCount() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
};

// Row by row from the top: index = x + y * width.
std::vector<Ray> frameRays(const Camera& camera);
std::vector<TValueRecord> makeFrameJobs(const Camera& camera, uint32_t root,
                                        double epsilon = kDefaultDirectionEpsilon);
// The world-space ray records of a frame for the model whose header is at `modelAddress`
// (directions normalised, so t is a world distance).
std::vector<RayRecord> makeFrameRayRecords(const Camera& camera, uint32_t modelAddress);

// "x,y,z" -> vector; throws std::invalid_argument naming `what` on malformed text.
glm::dvec3 parseVector(const std::string& text, const std::string& what);

}  // namespace rtu
