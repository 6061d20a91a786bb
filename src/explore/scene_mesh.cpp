#include "explore/scene_mesh.h"

#include <cstdio>
#include <stdexcept>

#include "base/output_file.h"
#include "explore/frame_scene.h"
#include "explore/reference_frame.h"

namespace rtu {
namespace {

void append(TriangleMesh& to, const TriangleMesh& mesh) {
  const auto base = static_cast<uint32_t>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
  for (const auto& triangle : mesh.triangles)
    to.triangles.push_back({triangle[0] + base, triangle[1] + base, triangle[2] + base});
}

}  // namespace

TriangleMesh sceneModelMesh(const ModelDescription& model) {
  try {
    const TriangleScene triangles = loadTriangleScene(model.source, MeshDefectPolicy::Drop);
    return placedMesh(triangles.mesh, framePlacement(model.source, triangles.mesh));
  } catch (const std::exception& error) {
    throw std::runtime_error("model '" + model.name + "': " + error.what());
  }
}

SceneMesh sceneMesh(const SceneDescription& scene, double time) {
  std::vector<TriangleMesh> models;
  for (const ModelDescription& model : scene.models) models.push_back(sceneModelMesh(model));
  SceneMesh out;
  for (const InstanceDescription& instance : scene.instances)
    append(out.mesh, placedMesh(models.at(instance.model), instance.placement.at(time)));
  out.camera = scene.camera.at(time, scene.width, scene.height);
  return out;
}

void writeObjMesh(const std::string& path, const TriangleMesh& mesh) {
  std::string text;
  char line[128];
  for (const glm::dvec3& v : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
    text += line;
  }
  for (const auto& t : mesh.triangles) {
    std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    text += line;
  }
  writeTextFile(path, text);
}

}  // namespace rtu
