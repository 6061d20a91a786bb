#include "app/accel_build.h"

#include <chrono>
#include <stdexcept>

#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_quality.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/lbvh_builder.h"
#include "kinds/bvh/sah_builder.h"

namespace rtu {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

BuildTree buildBvhTree(const TriangleMesh& mesh, const std::string& builder) {
  if (builder == "langr") return buildLangr(mesh).tree;
  if (builder == "lbvh") return buildLbvh(mesh).tree;
  SahBuilderConfig config;
  config.search = builder == "sweep" ? SahSplitSearch::Sweep : SahSplitSearch::Binned;
  return buildSah(mesh, config).tree;
}

AccelBuild bvhBuild(const TriangleMesh& mesh, const AccelSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  const BuildTree tree = buildBvhTree(mesh, spec.builder);
  AccelBuild build;
  build.words = layOut(tree, mesh).words;
  build.quality = measureQuality(tree, SahCosts{1.0, 2.0});  // seed 003's box 1, triangle 2
  build.quality.buildSeconds = secondsSince(start);
  build.description = spec.builder + " BVH";
  return build;
}

}  // namespace

AccelBuild buildAccel(const TriangleMesh& mesh, const AccelSpec& spec) {
  AccelBuild build;
  if (spec.structure == "bvh")
    build = bvhBuild(mesh, spec);
  else
    throw std::invalid_argument("no triangle structure '" + spec.structure + "' to build yet: bvh");
  build.quality.bytes = build.words.size() * sizeof(uint32_t);
  return build;
}

}  // namespace rtu
