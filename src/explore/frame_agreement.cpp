#include "explore/frame_agreement.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace rtu {
namespace {

// A hit's object under `rule`.
uint64_t objectOf(const Camera& camera, size_t pixel, double t, int64_t triangle,
                  const ObjectRule& rule) {
  return rule.voxels ? voxelAt(camera, pixel, t, rule.depth) : static_cast<uint64_t>(triangle);
}

PrecisionVerdict verdict(const Camera& camera, size_t i, const FrameHit& pixel,
                         const std::optional<OracleHit>& reference, const ObjectRule& rule) {
  if (!pixel.hit) return reference ? PrecisionVerdict::MissedHit : PrecisionVerdict::BothMiss;
  if (!reference) return PrecisionVerdict::FalseHit;
  const uint64_t mine = objectOf(camera, i, pixel.t, pixel.triangle, rule);
  const uint64_t theirs = objectOf(camera, i, reference->t, reference->triangle, rule);
  return mine == theirs ? PrecisionVerdict::Agree : PrecisionVerdict::DifferentVoxel;
}

void checkSizes(const std::vector<FrameHit>& frame,
                const std::vector<std::optional<OracleHit>>& reference) {
  if (frame.size() != reference.size())
    throw std::invalid_argument("a frame of " + std::to_string(frame.size()) +
                                " pixels against a reference of " +
                                std::to_string(reference.size()));
}

}  // namespace

uint64_t voxelAt(const Camera& camera, size_t pixel, double t, int depth) {
  const int x = static_cast<int>(pixel % camera.width), y = static_cast<int>(pixel / camera.width);
  const Ray ray = camera.primaryRay(x, y);
  const double cells = std::ldexp(1.0, depth);
  // A hundredth of a cell past the hit: inside the cell the ray enters there.
  const glm::dvec3 point = ray.origin + (t + 0.01 * 2 / cells) * glm::normalize(ray.direction);
  uint64_t packed = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const double cell = std::clamp(std::floor((point[axis] + 1) / 2 * cells), 0.0, cells - 1);
    packed = packed << 21 | static_cast<uint64_t>(cell);
  }
  return packed;
}

std::vector<PrecisionVerdict> pixelVerdicts(const Camera& camera,
                                            const std::vector<FrameHit>& frame,
                                            const std::vector<std::optional<OracleHit>>& reference,
                                            const ObjectRule& rule) {
  checkSizes(frame, reference);
  std::vector<PrecisionVerdict> verdicts;
  verdicts.reserve(reference.size());
  for (size_t i = 0; i < reference.size(); ++i)
    verdicts.push_back(verdict(camera, i, frame[i], reference[i], rule));
  return verdicts;
}

ImageAgreement imageAgreement(const Camera& camera, const std::vector<FrameHit>& frame,
                              const std::vector<std::optional<OracleHit>>& reference,
                              const ObjectRule& rule) {
  const std::vector<PrecisionVerdict> verdicts = pixelVerdicts(camera, frame, reference, rule);
  ImageAgreement a;
  a.pixels = verdicts.size();
  double depthErrors = 0;
  for (size_t i = 0; i < verdicts.size(); ++i) {
    switch (verdicts[i]) {
      case PrecisionVerdict::BothMiss: ++a.bothMiss; continue;
      case PrecisionVerdict::FalseHit: ++a.falseHits; continue;
      case PrecisionVerdict::MissedHit: ++a.missedHits; continue;
      case PrecisionVerdict::DifferentVoxel: ++a.otherObject; break;
      case PrecisionVerdict::Agree: break;
    }
    ++a.bothHit;
    const double error = std::abs(frame[i].t - reference[i]->t);
    depthErrors += error;
    a.maxDepthError = std::max(a.maxDepthError, error);
  }
  a.meanDepthError = a.bothHit ? depthErrors / a.bothHit : 0;
  return a;
}

}  // namespace rtu
