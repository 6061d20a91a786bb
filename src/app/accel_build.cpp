#include "app/accel_build.h"

#include <chrono>
#include <stdexcept>

#include "geometry/ray_sets.h"
#include "kinds/bih/bih_builder.h"
#include "kinds/bih/bih_image.h"
#include "kinds/bih/bih_quality.h"
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

AccelBuild bihBuild(const TriangleMesh& mesh, const AccelSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  const SceneGrid grid(meshBounds(mesh), spec.bihFormat == "vhdl" ? kVhdlFormat : kC99Format);
  const ProjectedMesh projected = projectMesh(mesh, grid);
  const BihBuild tree = buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid));
  const BihIndexWidth width = spec.bihIndex == "wide" ? BihIndexWidth::Wide : BihIndexWidth::Seed;
  BihImage image = layOut(tree, projected, grid, width);
  AccelBuild build;
  build.words = std::move(image.words);
  build.warnings = std::move(image.warnings);
  if (projected.degenerate > 0)
    build.warnings.push_back(std::to_string(projected.degenerate) +
                             " triangles have no area once on the grid and are left out");
  build.quality = measureQuality(tree, sceneUpper(grid));
  build.quality.buildSeconds = secondsSince(start);
  build.description = "BIH (" + spec.bihFormat + " formats, " + spec.bihIndex + " indices)";
  return build;
}

}  // namespace

AccelBuild buildAccel(const TriangleMesh& mesh, const AccelSpec& spec) {
  AccelBuild build;
  if (spec.structure == "bvh")
    build = bvhBuild(mesh, spec);
  else if (spec.structure == "bih")
    build = bihBuild(mesh, spec);
  else
    throw std::invalid_argument("no triangle structure '" + spec.structure + "': bvh or bih");
  build.quality.bytes = build.words.size() * sizeof(uint32_t);
  return build;
}

}  // namespace rtu
