#include "triangle_mesh.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "plugin_loader.h"

namespace rtu {
namespace {

void requireFinite(const TriangleMesh& mesh, const std::string& path) {
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3& v = mesh.vertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw std::runtime_error("mesh '" + path + "': vertex " + std::to_string(i) +
                               " has a non-finite coordinate");
  }
}

}  // namespace

TriangleMesh loadTriangleMesh(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("mesh file '" + path + "' does not exist");
  // assimp's part, in librtusim_meshes.so (stimuli/mesh_plugin.cpp).
  using LoadFunction = const char*(const char* path, void* mesh);
  static LoadFunction* const load = pluginFunction<LoadFunction>(
      "librtusim_meshes.so", "rtusim_meshes_load", "needed to read meshes");
  TriangleMesh mesh;
  if (const char* error = load(path.c_str(), &mesh))
    throw std::runtime_error("cannot read mesh '" + path + "': " + error);
  if (mesh.triangles.empty()) throw std::runtime_error("mesh '" + path + "' has no triangles");
  requireFinite(mesh, path);
  return mesh;
}

}  // namespace rtu
