#include "explore/accel_build.h"

#include <chrono>
#include <stdexcept>

#include "geometry/ray_sets.h"
#include "kinds/bih/bih_builder.h"
#include "kinds/bih/bih_config.h"
#include "kinds/bih/bih_image.h"
#include "kinds/bih/bih_quality.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_quality.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/lbvh_builder.h"
#include "kinds/bvh/sah_builder.h"
#include "kinds/kd/kd_image.h"
#include "kinds/kd/kd_quality.h"
#include "kinds/kd/trayracer_scene.h"

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

AccelBuild bihBuild(const TriangleMesh& mesh, const AccelSpec& spec,
                    const FixedTriangleFormat& format) {
  const auto start = std::chrono::steady_clock::now();
  const SceneGrid grid(meshBounds(mesh), format);
  const ProjectedMesh projected = projectMesh(mesh, grid);
  const BihBuild tree = buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid));
  const BihIndexWidth width = spec.index == "wide" ? BihIndexWidth::Wide : BihIndexWidth::Seed;
  BihImage image = layOut(tree, projected, grid, width);
  AccelBuild build;
  build.words = std::move(image.words);
  build.warnings = std::move(image.warnings);
  if (projected.degenerate > 0)
    build.warnings.push_back(std::to_string(projected.degenerate) +
                             " triangles have no area once on the grid and are left out");
  build.quality = measureQuality(tree, sceneUpper(grid));
  build.quality.buildSeconds = secondsSince(start);
  build.description = "BIH (" + bihFormatName(format) + " formats, " + spec.index + " indices)";
  return build;
}

// The colour section's one material: a mid grey, not specular.
const TrayRacerMaterial kGreyMaterial{glm::dvec3(0.8), 0.0};

// Three world-space corners per triangle and each triangle's unit normal, as the Tray Racer's
// scene file takes them.
void cornersAndNormals(const TriangleMesh& mesh, std::vector<glm::dvec3>& corners,
                       std::vector<glm::dvec3>& normals) {
  for (const auto& triangle : mesh.triangles) {
    for (uint32_t v : triangle) corners.push_back(mesh.vertices[v]);
    const glm::dvec3& a = mesh.vertices[triangle[0]];
    normals.push_back(
        glm::normalize(glm::cross(mesh.vertices[triangle[1]] - a, mesh.vertices[triangle[2]] - a)));
  }
}

AccelBuild kdBuild(const TriangleMesh& mesh, const AccelSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<glm::dvec3> corners, normals;
  cornersAndNormals(mesh, corners, normals);
  PbrtKdParameters parameters;
  parameters.edgeOrder = parseKdEdgeOrder(spec.kdEdgeOrder);
  const KdBuild tree = buildPbrtKd(pbrtTriangleBoxes(corners), parameters);
  const TrayRacerScene scene = makeTrayRacerScene(tree, corners, normals, kGreyMaterial);
  AccelBuild build;
  build.words = layOutKd(scene).words;
  build.sceneFile = writeTrayRacerScene(scene, spec.index == "wide" ? TrayRacerFormat::Wide
                                                                    : TrayRacerFormat::Narrow);
  build.warnings = trayRacerCapacityWarnings(scene);
  build.quality = measureQuality(tree, parameters);
  build.quality.buildSeconds = secondsSince(start);
  const std::string order = parameters.edgeOrder == KdEdgeOrder::EndFirst ? "R1's edge order, "
                            : parameters.edgeOrder == KdEdgeOrder::StartFirst
                                ? "PBRT's edge order, "
                                : "";
  build.description = "k-d tree (PBRT v1 SAH, " + order + spec.index + " scene file)";
  return build;
}

}  // namespace

AccelBuild buildAccel(const TriangleMesh& mesh, const AccelSpec& spec,
                      const FixedTriangleFormat& bihFormat) {
  AccelBuild build;
  if (spec.structure == "bvh")
    build = bvhBuild(mesh, spec);
  else if (spec.structure == "bih")
    build = bihBuild(mesh, spec, bihFormat);
  else if (spec.structure == "kdtree")
    build = kdBuild(mesh, spec);
  else
    throw std::invalid_argument("no triangle structure '" + spec.structure +
                                "': bvh, bih or kdtree");
  build.quality.bytes = build.words.size() * sizeof(uint32_t);
  return build;
}

TriangleScene loadSceneTriangles(const RunConfig& settings) {
  const MeshDefectPolicy policy = settings.accel.dropBadTriangles ? MeshDefectPolicy::Drop
                                                                  : MeshDefectPolicy::Refuse;
  try {
    return loadTriangleScene(settings.scene, policy);
  } catch (const DroppableMeshDefects& error) {
    throw std::runtime_error(std::string(error.what()) + "; drop them with --drop-bad-triangles");
  }
}

}  // namespace rtu
