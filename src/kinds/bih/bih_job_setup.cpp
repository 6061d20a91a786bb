#include "kinds/bih/bih_job_setup.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kinds/bih/bih_image.h"
#include "kinds/bih/bih_intersectors.h"

namespace rtu {
namespace {

// The grid of a scene box [0, upper] in grid units: scale 1 when the longest side is 2^n - 1.
SceneGrid gridOf(const BihScene& scene, const std::string& where) {
  Aabb<double> box;
  box.lower = glm::dvec3(0.0);
  box.upper = glm::dvec3(scene.upper[0], scene.upper[1], scene.upper[2]);
  try {
    return SceneGrid(box, scene.format);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(where + ": " + e.what());
  }
}

// An any-hit ray's segment ends at world t = 1: on the grid ray, floor((1 - tClip) / (a grid unit
// of t)); a segment that ends before the box begins meets nothing.
void limitToSegment(BihJob& job) {
  job.anyHit = true;
  if (job.missesBox) return;
  const double end = std::floor((1.0 - job.ray.tClip) / job.ray.worldPerGridUnit);
  if (end < 0)
    job.missesBox = true;
  else
    job.tLimit = static_cast<int64_t>(std::min(end, static_cast<double>(kC99NoHitYet)));
}

}  // namespace

BihJobSetup::Model BihJobSetup::readModel(uint32_t address) const {
  // Its sections start on multiples of 4 words from it (bih_image.h): so do the core's accesses.
  const ImageEntry entry = readImageEntry(
      memory_, address, BihTraversal<C99Intersector>::kWordsPerRead, kBihMagic, kBihKind, "BIH");
  BihScene scene = sceneOf(decodeBihHeader(entry.header.data()));
  const uint32_t root = entry.model.root;
  scene.nodes += root;
  scene.list += root;
  scene.triangles += root;
  return Model{entry.model, scene, gridOf(scene, entry.where)};
}

JobSetUp<BihJob> BihJobSetup::setUp(const RayRecord& record) {
  JobSetUp<BihJob> set;
  const Model& model =
      models_.find(record, set, [this](uint32_t address) { return readModel(address); });
  const ModelSpaceRay ray = toModelSpace(record, model.transform);
  const Ray onGrid{glm::dvec3(ray.origin[0], ray.origin[1], ray.origin[2]),
                   glm::dvec3(ray.direction[0], ray.direction[1], ray.direction[2])};
  set.job.scene = model.scene;
  // A direction that float32 rounded to 0 (a tiny one scaled down) reaches nothing.
  const bool moves = onGrid.direction != glm::dvec3(0.0);
  const std::optional<GridRay> clipped = moves ? model.grid.quantise(onGrid)
                                               : std::optional<GridRay>();
  if (clipped)
    set.job.ray = *clipped;
  else
    set.job.missesBox = true;
  if (record.span == RaySpan::AnyHit) limitToSegment(set.job);
  return set;
}

}  // namespace rtu
