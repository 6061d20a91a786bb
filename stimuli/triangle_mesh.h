#pragma once
// A triangle soup with shared vertices, as read from a mesh file, before voxelization.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace rtu {

struct TriangleMesh {
  std::vector<glm::dvec3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into `vertices`
};

// Reads OBJ or PLY (ASCII or binary) through assimp: polygons are triangulated, identical
// vertices joined, every mesh of the scene merged with its node transforms applied. Points and
// lines are dropped. Throws std::runtime_error naming `path` when the file is missing, assimp
// cannot read it, it holds no triangle or a coordinate is not finite. assimp is called in
// librtusim_meshes.so (mesh_plugin.cpp), loaded on first use (plugin_loader.h): a missing
// module is a std::runtime_error naming it.
TriangleMesh loadTriangleMesh(const std::string& path);

}  // namespace rtu
