#include "kinds/bvh/app/bvh_golden.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "rtu/golden_shell.h"

namespace rtu {
namespace {

std::vector<BvhJob> jobsOf(const std::vector<uint32_t>& image, const std::vector<RayRecord>& rays,
                           const std::string& raysPath) {
  const BvhSections sections = sectionsOf(decodeHeader(image.data()));
  std::vector<BvhJob> jobs;
  jobs.reserve(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    const RayRecord& ray = rays[i];
    if (ray.modelAddress != 0)
      throw std::runtime_error("ray buffer '" + raysPath + "': record " + std::to_string(i) +
                               " names model address " + std::to_string(ray.modelAddress) +
                               "; a BVH image has no model headers: give 0");
    const Vec3<float> origin(ray.origin[0], ray.origin[1], ray.origin[2]);
    const Vec3<float> direction(ray.direction[0], ray.direction[1], ray.direction[2]);
    jobs.push_back({makeBvhRay(origin, direction, 0.0f, INFINITY), sections});
  }
  return jobs;
}

template <class Intersector>
BvhGoldenRun trace(const std::vector<uint32_t>& image, const std::vector<BvhJob>& jobs,
                   const std::vector<RayRecord>& rays) {
  GoldenShell<BvhKind<Intersector>> shell(WordMemory(image), BvhConfig{});
  BvhGoldenRun run;
  run.results.resize(jobs.size());
  const auto start = std::chrono::steady_clock::now();
  for (size_t i = 0; i < jobs.size(); ++i) shell.run(rays[i].id, jobs[i], run.results[i]);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace

BvhGoldenRun traceBvhGolden(const std::vector<uint32_t>& image, const std::vector<RayRecord>& rays,
                            const std::string& raysPath, TriangleTest triangleTest) {
  const std::vector<BvhJob> jobs = jobsOf(image, rays, raysPath);
  if (triangleTest == TriangleTest::MollerTrumbore)
    return trace<MollerTrumboreIntersector>(image, jobs, rays);
  return trace<WatertightIntersector>(image, jobs, rays);
}

}  // namespace rtu
