#include "kinds/kd/explore/kd_scene.h"

#include <glm/geometric.hpp>

#include "kinds/kd/kd_image.h"
#include "kinds/kd/kd_quality.h"
#include "kinds/kd/trayracer_scene.h"

namespace rtu {
namespace {

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

std::string edgeOrderWords(KdEdgeOrder order) {
  if (order == KdEdgeOrder::EndFirst) return "R1's edge order, ";
  if (order == KdEdgeOrder::StartFirst) return "PBRT's edge order, ";
  return "";
}

}  // namespace

AccelBuild KindScene<KdKind>::build(const TriangleMesh& mesh, const AccelSpec& spec,
                                    const RtuConfig&) {
  std::vector<glm::dvec3> corners, normals;
  cornersAndNormals(mesh, corners, normals);
  PbrtKdParameters parameters;
  parameters.edgeOrder = parseKdEdgeOrder(spec.kdEdgeOrder);
  const KdBuild tree = buildPbrtKd(pbrtTriangleBoxes(corners), parameters);
  const KdMatrixColumn column = parseKdMatrixColumn(spec.kdMatrix);
  const TrayRacerScene scene = makeTrayRacerScene(tree, corners, normals, kGreyMaterial, column);
  AccelBuild build;
  build.words = layOutKd(scene).words;
  build.sceneFile = writeTrayRacerScene(scene, spec.index == "wide" ? TrayRacerFormat::Wide
                                                                    : TrayRacerFormat::Narrow);
  build.warnings = trayRacerCapacityWarnings(scene);
  build.quality = measureQuality(tree, parameters);
  build.settings = {
      {"builder", "pbrt"}, {"kd_edge_order", spec.kdEdgeOrder}, {"kd_matrix", spec.kdMatrix}};
  build.description = "k-d tree (PBRT v1 SAH, " + edgeOrderWords(parameters.edgeOrder) +
                      (column == KdMatrixColumn::NormalMinusC ? "R1's matrices, " : "") +
                      spec.index + " scene file)";
  return build;
}

}  // namespace rtu
