// Mesh checks before a triangle build (geometry/mesh_checks.h): every class of defect found and
// named, the fatal ones refused whatever the policy, degenerate and duplicate ones dropped on
// request with the rest kept in order.
#include <catch2/catch.hpp>

#include <limits>

#include "geometry/mesh_checks.h"

namespace rtu {
namespace {

// Four vertices of a unit square at z = 0 and a fifth on the diagonal's midpoint.
TriangleMesh square() {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

std::string refusal(TriangleMesh mesh, MeshDefectPolicy policy) {
  try {
    checkTriangleMesh(mesh, "square.obj", policy);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_CASE("Mesh checks: a sound mesh passes unchanged", "[mesh_checks]") {
  TriangleMesh mesh = square();
  const MeshDefects defects = findMeshDefects(mesh);
  CHECK_FALSE(defects.fatal());
  CHECK_FALSE(defects.droppable());
  CHECK(checkTriangleMesh(mesh, "square.obj", MeshDefectPolicy::Refuse).empty());
  CHECK(mesh.triangles.size() == 2);
}

TEST_CASE("Mesh checks: degenerate triangles, repeated or collinear vertices", "[mesh_checks]") {
  TriangleMesh mesh = square();
  mesh.triangles.push_back({1, 1, 2});  // 2: a repeated index
  mesh.triangles.push_back({0, 4, 2});  // 3: collinear along the diagonal
  const MeshDefects defects = findMeshDefects(mesh);
  CHECK(defects.degenerate == std::vector<uint32_t>{2, 3});
  CHECK(defects.duplicate.empty());
  CHECK(refusal(mesh, MeshDefectPolicy::Refuse) ==
        "square.obj: 2 degenerate (zero-area) triangles: triangle (2, 3)");
  TriangleMesh copy = mesh;
  CHECK_THROWS_AS(checkTriangleMesh(copy, "square.obj", MeshDefectPolicy::Refuse),
                  DroppableMeshDefects);
  CHECK(checkTriangleMesh(mesh, "square.obj", MeshDefectPolicy::Drop) ==
        std::vector<uint32_t>{2, 3});
  CHECK(mesh.triangles == square().triangles);
}

TEST_CASE("Mesh checks: duplicates in any vertex order, the later one named", "[mesh_checks]") {
  TriangleMesh mesh = square();
  mesh.triangles.push_back({2, 0, 1});  // 2: triangle 0 rotated
  mesh.triangles.push_back({0, 3, 2});  // 3: triangle 1 with its winding flipped
  mesh.vertices.push_back({1, 1, 0});   // 5: vertex 2 again, under another index
  mesh.triangles.push_back({0, 1, 5});  // 4: triangle 0 through the copy
  mesh.triangles.push_back({1, 2, 3});  // 5: overlaps but is another triangle
  const MeshDefects defects = findMeshDefects(mesh);
  CHECK(defects.duplicate == std::vector<uint32_t>{2, 3, 4});
  CHECK(refusal(mesh, MeshDefectPolicy::Refuse) ==
        "square.obj: 3 duplicate triangles (the same vertices as an earlier one): triangle (2, 3, "
        "4)");
  CHECK(checkTriangleMesh(mesh, "square.obj", MeshDefectPolicy::Drop) ==
        std::vector<uint32_t>{2, 3, 4});
  CHECK(mesh.triangles == std::vector<std::array<uint32_t, 3>>{{0, 1, 2}, {0, 2, 3}, {1, 2, 3}});
}

TEST_CASE("Mesh checks: both droppable classes named in one message", "[mesh_checks]") {
  TriangleMesh mesh = square();
  mesh.triangles.push_back({3, 3, 3});
  mesh.triangles.push_back({1, 2, 0});
  CHECK(refusal(mesh, MeshDefectPolicy::Refuse) ==
        "square.obj: 1 degenerate (zero-area) triangles: triangle (2); 1 duplicate triangles (the "
        "same vertices as an earlier one): triangle (3)");
}

TEST_CASE("Mesh checks: fatal defects are refused even when dropping", "[mesh_checks]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  SECTION("a coordinate that is not finite") {
    TriangleMesh mesh = square();
    mesh.vertices[3].y = nan;
    mesh.vertices[4].z = std::numeric_limits<double>::infinity();
    const MeshDefects defects = findMeshDefects(mesh);
    CHECK(defects.nonFiniteVertices == std::vector<uint32_t>{3, 4});
    CHECK(defects.degenerate.empty());  // triangle 1 touches vertex 3: not judged
    CHECK(refusal(mesh, MeshDefectPolicy::Drop) ==
          "square.obj: 2 vertices with a coordinate that is not finite: vertex (3, 4)");
  }
  SECTION("an index past the vertices") {
    TriangleMesh mesh = square();
    mesh.triangles.push_back({0, 1, 5});
    CHECK(findMeshDefects(mesh).indexOutOfRange == std::vector<uint32_t>{2});
    CHECK(refusal(mesh, MeshDefectPolicy::Drop) ==
          "square.obj: 1 triangles with a vertex index past the vertices: triangle (2)");
  }
  SECTION("no triangle, or none left") {
    TriangleMesh empty;
    CHECK(refusal(empty, MeshDefectPolicy::Drop) == "square.obj: the mesh has no triangle");
    TriangleMesh flat = square();
    flat.triangles = {{0, 4, 2}};
    CHECK(refusal(flat, MeshDefectPolicy::Drop) ==
          "square.obj: no triangle is left after dropping bad ones");
  }
}

TEST_CASE("Mesh checks: at most five indices shown", "[mesh_checks]") {
  TriangleMesh mesh = square();
  for (int i = 0; i < 7; ++i) mesh.triangles.push_back({0, 0, 1});
  CHECK(refusal(mesh, MeshDefectPolicy::Refuse) ==
        "square.obj: 7 degenerate (zero-area) triangles: triangle (2, 3, 4, 5, 6, ...)");
}

}  // namespace rtu
