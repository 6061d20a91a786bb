#include "kinds/bvh/build_primitives.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace rtu {
namespace {

constexpr double kMaxCoordinate = 0x1p1000;

void checkMesh(const TriangleMesh& mesh, const std::string& builder) {
  if (mesh.triangles.empty())
    throw std::invalid_argument(builder + " builder: the mesh has no triangles");
  if (mesh.triangles.size() > std::numeric_limits<uint32_t>::max())
    throw std::invalid_argument(builder + " builder: " + std::to_string(mesh.triangles.size()) +
                                " triangles, more than 32-bit references can name");
  for (const glm::dvec3& vertex : mesh.vertices)
    for (int k = 0; k < 3; ++k)
      if (!(std::abs(vertex[k]) <= kMaxCoordinate))
        throw std::invalid_argument(builder + " builder: a vertex coordinate (" +
                                    std::to_string(vertex[k]) +
                                    ") is not finite or beyond 2^1000 in magnitude");
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (uint32_t index : mesh.triangles[t])
      if (index >= mesh.vertices.size())
        throw std::invalid_argument(builder + " builder: triangle " + std::to_string(t) +
                                    " names vertex " + std::to_string(index) + " of " +
                                    std::to_string(mesh.vertices.size()));
}

}  // namespace

Aabb<double> BuildPrimitives::boxOf(const std::vector<uint32_t>& refs, uint32_t first,
                                    uint32_t count) const {
  Aabb<double> box;
  for (uint32_t i = first; i < first + count; ++i) box.merge(boxes[refs[i]]);
  return box;
}

BuildPrimitives buildPrimitives(const TriangleMesh& mesh, const std::string& builder) {
  checkMesh(mesh, builder);
  BuildPrimitives primitives;
  primitives.boxes.reserve(mesh.triangles.size());
  primitives.centres.reserve(mesh.triangles.size());
  for (const auto& triangle : mesh.triangles) {
    Aabb<double> box;
    for (uint32_t index : triangle) box.grow(mesh.vertices[index]);
    primitives.boxes.push_back(box);
    primitives.centres.push_back(box.centre());
  }
  return primitives;
}

BuildPrimitives boxPrimitives(std::vector<Aabb<double>> boxes) {
  BuildPrimitives primitives;
  primitives.centres.reserve(boxes.size());
  for (const Aabb<double>& box : boxes) primitives.centres.push_back(box.centre());
  primitives.boxes = std::move(boxes);
  return primitives;
}

void checkPrimitives(const BuildPrimitives& primitives, const std::string& builder) {
  const size_t count = primitives.boxes.size();
  if (count == 0) throw std::invalid_argument(builder + " builder: no primitives to build over");
  if (count > std::numeric_limits<uint32_t>::max())
    throw std::invalid_argument(builder + " builder: " + std::to_string(count) +
                                " primitives, more than 32-bit references can name");
  if (primitives.centres.size() != count)
    throw std::invalid_argument(builder + " builder: " + std::to_string(count) + " boxes but " +
                                std::to_string(primitives.centres.size()) + " centres");
  const auto bounded = [](const glm::dvec3& p) {
    return std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate &&
           std::abs(p.z) <= kMaxCoordinate;
  };
  for (size_t i = 0; i < count; ++i) {
    const Aabb<double>& box = primitives.boxes[i];
    if (box.empty() || !bounded(box.lower) || !bounded(box.upper) ||
        !bounded(primitives.centres[i]))
      throw std::invalid_argument(builder + " builder: primitive " + std::to_string(i) +
                                  " has an empty box or a bound not finite or beyond 2^1000");
  }
}

int widestAxis(const Aabb<double>& box) {
  const glm::dvec3 extent = box.extent();
  int axis = 0;
  if (extent.y > extent[axis]) axis = 1;
  if (extent.z > extent[axis]) axis = 2;
  return axis;
}

}  // namespace rtu
