// Voxel scenes as triangles (kinds/svo/voxel_faces.h): faces counted by hand on small grids,
// outward winding, shared vertices, and the two kinds' independent oracles agreeing on the same
// surface: the SVO's float64 voxel walk and the triangle oracle over the faces.
#include <catch2/catch.hpp>

#include <set>
#include <tuple>

#include <glm/geometric.hpp>

#include "geometry/ray_sets.h"
#include "geometry/triangle_oracle.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_voxel_walk.h"
#include "kinds/svo/voxel_faces.h"

namespace rtu {
namespace {

// Solid exactly at the listed voxels of a 2^depth grid; Mixed above the voxels.
class ListedVoxels : public VoxelSource {
 public:
  ListedVoxels(int depth, std::set<std::tuple<uint32_t, uint32_t, uint32_t>> solid)
      : depth_(depth), solid_(std::move(solid)) {}
  int depth() const override { return depth_; }
  Occupancy classify(const OctreeNode& node) const override {
    if (node.level < depth_) return Occupancy::Mixed;
    return solid_.count({node.x, node.y, node.z}) ? Occupancy::Full : Occupancy::Empty;
  }

 private:
  int depth_;
  std::set<std::tuple<uint32_t, uint32_t, uint32_t>> solid_;
};

// Everything solid, said at the root.
class AllSolid : public VoxelSource {
 public:
  int depth() const override { return 1; }
  Occupancy classify(const OctreeNode&) const override { return Occupancy::Full; }
};

glm::dvec3 normalOf(const TriangleMesh& mesh, const std::array<uint32_t, 3>& t) {
  const glm::dvec3 a = mesh.vertices[t[0]];
  return glm::cross(mesh.vertices[t[1]] - a, mesh.vertices[t[2]] - a);
}

glm::dvec3 centreOf(const TriangleMesh& mesh, const std::array<uint32_t, 3>& t) {
  return (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
}

}  // namespace

TEST_CASE("Voxel faces: one voxel is a cube of 12 triangles winding outward", "[voxel_faces]") {
  // Voxel (1, 0, 1) of the 2-voxel grid spans [0,1] x [-1,0] x [0,1].
  const TriangleMesh mesh = voxelFaces(ListedVoxels(1, {{1, 0, 1}}));
  CHECK(mesh.triangles.size() == 12);
  CHECK(mesh.vertices.size() == 8);
  const glm::dvec3 centre(0.5, -0.5, 0.5);
  for (const auto& t : mesh.triangles) {
    const glm::dvec3 n = normalOf(mesh, t);
    CHECK(glm::length(n) == 1.0);  // half a unit square: |cross| = 1
    CHECK(glm::dot(n, centreOf(mesh, t) - centre) > 0);
  }
  for (const glm::dvec3& v : mesh.vertices) {
    CHECK((v.x == 0.0 || v.x == 1.0));
    CHECK((v.y == -1.0 || v.y == 0.0));
  }
}

TEST_CASE("Voxel faces: a face between two solid voxels is not made", "[voxel_faces]") {
  // Two voxels side by side along y: 10 faces, 12 corners.
  const TriangleMesh mesh = voxelFaces(ListedVoxels(2, {{1, 1, 2}, {1, 2, 2}}));
  CHECK(mesh.triangles.size() == 20);
  CHECK(mesh.vertices.size() == 12);
  // Diagonal neighbours share only an edge: both keep all 6 faces, sharing 2 vertices.
  const TriangleMesh diagonal = voxelFaces(ListedVoxels(2, {{0, 0, 0}, {1, 1, 0}}));
  CHECK(diagonal.triangles.size() == 24);
  CHECK(diagonal.vertices.size() == 14);
}

TEST_CASE("Voxel faces: a full grid shows only its outside", "[voxel_faces]") {
  // 2 x 2 x 2 voxels, all solid: 4 faces per side of the cube, the 26 outer points of 3 x 3 x 3.
  const TriangleMesh mesh = voxelFaces(AllSolid());
  CHECK(mesh.triangles.size() == 6 * 4 * 2);
  CHECK(mesh.vertices.size() == 26);
  for (const auto& t : mesh.triangles) CHECK(glm::dot(normalOf(mesh, t), centreOf(mesh, t)) > 0);
}

TEST_CASE("Voxel faces: too deep a grid is refused", "[voxel_faces]") {
  CHECK_THROWS_WITH(voxelFaces(ListedVoxels(10, {})),
                    "voxel faces: depth 10 is beyond the deepest grid they are made for (9)");
}

TEST_CASE("Voxel faces: the SVO walk and the triangle oracle see the same surface",
          "[voxel_faces]") {
  const std::string name = GENERATE("sphere", "menger", "terrain");
  const auto scene = makeProceduralScene(name, 5);
  const TriangleMesh mesh = voxelFaces(*scene);
  const SvoBuild build = buildSvo(*scene);
  const WordMemory memory = build.image.memory();
  int hits = 0, agree = 0, grazing = 0;
  for (const Ray& ray : viewRays(Aabb<double>{glm::dvec3(-1), glm::dvec3(1)}, 2, 16, 16)) {
    const VoxelWalkResult walk = walkVoxels(memory, build.image.root, ray.origin, ray.direction);
    const auto triangle = closestHit(mesh, ray, 0, INFINITY);
    hits += walk.hit;
    const bool same =
        walk.hit == triangle.has_value() && (!walk.hit || std::abs(walk.tHit - triangle->t) < 1e-9);
    // A ray within 1e-9 of the voxel grid's edges may be decided either way by either oracle.
    if (same)
      ++agree;
    else if (walk.clearance < 1e-9)
      ++grazing;
    else
      FAIL_CHECK(name << ": the walk says " << walk.hit << " at " << walk.tHit << ", the triangles "
                      << triangle.has_value());
  }
  INFO(name << ": " << hits << " hits, " << agree << " agree, " << grazing << " grazing");
  CHECK(hits > 50);
  CHECK(agree + grazing == 2 * 16 * 16);
}

}  // namespace rtu
