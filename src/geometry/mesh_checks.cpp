#include "geometry/mesh_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace rtu {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool inRange(const std::array<uint32_t, 3>& triangle, size_t vertices) {
  return std::all_of(triangle.begin(), triangle.end(), [&](uint32_t i) { return i < vertices; });
}

// A triangle's three vertex positions sorted, so that the same triangle in any vertex order or
// winding has the same key.
using TriangleKey = std::array<std::array<double, 3>, 3>;

TriangleKey keyOf(const TriangleMesh& mesh, const std::array<uint32_t, 3>& triangle) {
  TriangleKey key;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3& v = mesh.vertices[triangle[i]];
    key[i] = {v.x, v.y, v.z};
  }
  std::sort(key.begin(), key.end());
  return key;
}

bool degenerate(const TriangleMesh& mesh, const std::array<uint32_t, 3>& triangle) {
  const glm::dvec3& a = mesh.vertices[triangle[0]];
  const glm::dvec3 normal =
      glm::cross(mesh.vertices[triangle[1]] - a, mesh.vertices[triangle[2]] - a);
  return normal == glm::dvec3(0);
}

// Triangles equal by key to a lower-indexed one, in increasing index order.
std::vector<uint32_t> duplicates(const TriangleMesh& mesh,
                                 const std::vector<uint32_t>& candidates) {
  std::vector<std::pair<TriangleKey, uint32_t>> keyed;
  keyed.reserve(candidates.size());
  for (uint32_t t : candidates) keyed.emplace_back(keyOf(mesh, mesh.triangles[t]), t);
  std::sort(keyed.begin(), keyed.end());
  std::vector<uint32_t> found;
  for (size_t i = 1; i < keyed.size(); ++i)
    if (keyed[i].first == keyed[i - 1].first) found.push_back(keyed[i].second);
  std::sort(found.begin(), found.end());
  return found;
}

std::string describe(const std::string& what, const std::vector<uint32_t>& indices) {
  constexpr size_t kShown = 5;
  std::ostringstream text;
  text << indices.size() << ' ' << what << " (";
  for (size_t i = 0; i < std::min(indices.size(), kShown); ++i)
    text << (i ? ", " : "") << indices[i];
  text << (indices.size() > kShown ? ", ...)" : ")");
  return text.str();
}

[[noreturn]] void refuse(const std::string& source, const std::string& problem) {
  throw std::runtime_error(source + ": " + problem);
}

void refuseFatal(const std::string& source, const MeshDefects& defects) {
  if (!defects.nonFiniteVertices.empty())
    refuse(source, describe("vertices with a coordinate that is not finite: vertex",
                            defects.nonFiniteVertices));
  if (!defects.indexOutOfRange.empty())
    refuse(source, describe("triangles with a vertex index past the vertices: triangle",
                            defects.indexOutOfRange));
}

[[noreturn]] void refuseDroppable(const std::string& source, const MeshDefects& defects) {
  std::string problem;
  if (!defects.degenerate.empty())
    problem = describe("degenerate (zero-area) triangles: triangle", defects.degenerate);
  if (!defects.duplicate.empty())
    problem += (problem.empty() ? "" : "; ") +
               describe("duplicate triangles (the same vertices as an earlier one): triangle",
                        defects.duplicate);
  throw DroppableMeshDefects(source + ": " + problem);
}

std::vector<uint32_t> dropTriangles(TriangleMesh& mesh, const MeshDefects& defects) {
  std::vector<uint32_t> dropped = defects.degenerate;
  dropped.insert(dropped.end(), defects.duplicate.begin(), defects.duplicate.end());
  std::sort(dropped.begin(), dropped.end());
  std::vector<std::array<uint32_t, 3>> kept;
  kept.reserve(mesh.triangles.size() - dropped.size());
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t)
    if (!std::binary_search(dropped.begin(), dropped.end(), t)) kept.push_back(mesh.triangles[t]);
  mesh.triangles = std::move(kept);
  return dropped;
}

}  // namespace

MeshDefects findMeshDefects(const TriangleMesh& mesh) {
  MeshDefects defects;
  std::vector<bool> vertexFinite(mesh.vertices.size());
  for (uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    vertexFinite[v] = finite(mesh.vertices[v]);
    if (!vertexFinite[v]) defects.nonFiniteVertices.push_back(v);
  }
  std::vector<uint32_t> sound;  // in range, finite and not degenerate
  for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& triangle = mesh.triangles[t];
    if (!inRange(triangle, mesh.vertices.size())) {
      defects.indexOutOfRange.push_back(t);
    } else if (std::all_of(triangle.begin(), triangle.end(),
                           [&](uint32_t v) { return vertexFinite[v]; })) {
      if (degenerate(mesh, triangle))
        defects.degenerate.push_back(t);
      else
        sound.push_back(t);
    }
  }
  defects.duplicate = duplicates(mesh, sound);
  return defects;
}

std::vector<uint32_t> checkTriangleMesh(TriangleMesh& mesh, const std::string& source,
                                        MeshDefectPolicy policy) {
  if (mesh.triangles.empty()) refuse(source, "the mesh has no triangle");
  const MeshDefects defects = findMeshDefects(mesh);
  refuseFatal(source, defects);
  if (!defects.droppable()) return {};
  if (policy == MeshDefectPolicy::Refuse) refuseDroppable(source, defects);
  std::vector<uint32_t> dropped = dropTriangles(mesh, defects);
  if (mesh.triangles.empty()) refuse(source, "no triangle is left after dropping bad ones");
  return dropped;
}

}  // namespace rtu
