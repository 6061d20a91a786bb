#pragma once
// Meshes for the BVH tests: rows of triangles whose boxes and centres are exact by hand, and
// the assimp test models of Debian's assimp-testmodels, read once per test run.

#include <map>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.h"

namespace rtu {

// Triangle i is (x - 1/2, 0, 0), (x + 1/2, 0, 0), (x - 1/2, 1, 0) with x = centres[i]: its box is
// [x - 1/2, x + 1/2] x [0, 1] x [0, 0], of area 2 (width x 1), centred on (x, 1/2, 0). A box
// around triangles of centres a..b therefore has area 2 (b - a + 1).
inline TriangleMesh rowOfTriangles(const std::vector<double>& centres) {
  TriangleMesh mesh;
  for (double x : centres) {
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back({x - 0.5, 0, 0});
    mesh.vertices.push_back({x + 0.5, 0, 0});
    mesh.vertices.push_back({x - 0.5, 1, 0});
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

// Centres 0, 1, ..., count - 1 in order.
inline TriangleMesh rowOfTriangles(int count) {
  std::vector<double> centres;
  for (int i = 0; i < count; ++i) centres.push_back(i);
  return rowOfTriangles(centres);
}

// /usr/share/assimp/models/OBJ/<name>, loaded at the first call.
inline const TriangleMesh& assimpObjModel(const std::string& name) {
  static std::map<std::string, TriangleMesh> loaded;
  auto found = loaded.find(name);
  if (found == loaded.end())
    found = loaded.emplace(name, loadTriangleMesh("/usr/share/assimp/models/OBJ/" + name)).first;
  return found->second;
}

}  // namespace rtu
