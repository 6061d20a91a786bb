// Mesh loading (OBJ, PLY, node transforms, errors) and surface voxelization.
#include <sys/resource.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <glm/vector_relational.hpp>

#include "geometry/triangle_mesh.h"
#include "kinds/svo/mesh_voxelizer.h"
#include "kinds/svo/svo_builder.h"

using namespace rtu;
using Catch::Matchers::Contains;

namespace {

// A file in the temp directory, unique to this process, removed at the end of the test.
class TempFile {
 public:
  TempFile(const std::string& name, const std::string& contents)
      : path_(std::filesystem::temp_directory_path() /
              ("rtusim-mesh-" + std::to_string(getpid()) + "-" + name)) {
    std::ofstream(path_, std::ios::binary) << contents;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

const char* const kCubeObj = R"(# unit cube [2,3] x [-1,0] x [5,6], quads
v 2 -1 5
v 3 -1 5
v 3 0 5
v 2 0 5
v 2 -1 6
v 3 -1 6
v 3 0 6
v 2 0 6
f 1 4 3 2
f 5 6 7 8
f 1 2 6 5
f 2 3 7 6
f 3 4 8 7
f 4 1 5 8
)";

const TriangleMesh kTetrahedron = {{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}},
                                   {{{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}}};

std::string plyHeader(const std::string& format) {
  return "ply\nformat " + format +
         " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string asciiTetrahedronPly() {
  std::string ply = plyHeader("ascii");
  for (const glm::dvec3& v : kTetrahedron.vertices)
    ply += std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "\n";
  for (const auto& face : kTetrahedron.triangles)
    ply += "3 " + std::to_string(face[0]) + " " + std::to_string(face[1]) + " " +
           std::to_string(face[2]) + "\n";
  return ply;
}

template <typename T>
void appendBytes(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// Little-endian binary PLY of the tetrahedron; `firstX` replaces vertex 0's x.
std::string binaryTetrahedronPly(float firstX) {
  std::string ply = plyHeader("binary_little_endian");
  for (size_t i = 0; i < kTetrahedron.vertices.size(); ++i) {
    const glm::dvec3& v = kTetrahedron.vertices[i];
    appendBytes(ply, i == 0 ? firstX : static_cast<float>(v.x));
    appendBytes(ply, static_cast<float>(v.y));
    appendBytes(ply, static_cast<float>(v.z));
  }
  for (const auto& face : kTetrahedron.triangles) {
    appendBytes(ply, uint8_t{3});
    for (uint32_t index : face) appendBytes(ply, static_cast<int32_t>(index));
  }
  return ply;
}

std::multiset<std::tuple<double, double, double>> vertexSet(const TriangleMesh& mesh) {
  std::multiset<std::tuple<double, double, double>> set;
  for (const glm::dvec3& v : mesh.vertices) set.emplace(v.x, v.y, v.z);
  return set;
}

using VoxelSet = std::set<std::tuple<uint32_t, uint32_t, uint32_t>>;

// Every voxel of a 2^depth grid for which `solid` holds.
VoxelSet voxelsWhere(int depth, const std::function<bool(const OctreeNode&)>& solid) {
  VoxelSet set;
  const uint32_t cells = 1u << depth;
  for (uint32_t x = 0; x < cells; ++x)
    for (uint32_t y = 0; y < cells; ++y)
      for (uint32_t z = 0; z < cells; ++z)
        if (solid(OctreeNode{depth, x, y, z})) set.emplace(x, y, z);
  return set;
}

// The voxels a depth-first descent sees, in the builder's order (which the cache relies on).
void collectDepthFirst(const VoxelSource& source, const OctreeNode& node, VoxelSet& out) {
  const Occupancy occupancy = source.classify(node);
  if (occupancy == Occupancy::Mixed) {
    for (int slot = 0; slot < 8; ++slot) collectDepthFirst(source, node.child(slot), out);
  } else if (occupancy == Occupancy::Full) {
    const uint32_t span = 1u << (source.depth() - node.level);
    for (uint32_t x = 0; x < span; ++x)
      for (uint32_t y = 0; y < span; ++y)
        for (uint32_t z = 0; z < span; ++z)
          out.emplace(node.x * span + x, node.y * span + y, node.z * span + z);
  }
}

// The solid voxels as the builder would see them.
VoxelSet solidVoxels(const VoxelSource& source) {
  VoxelSet depthFirst;
  collectDepthFirst(source, OctreeNode{}, depthFirst);
  return depthFirst;
}

TriangleMesh singleTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return TriangleMesh{{a, b, c}, {{0, 1, 2}}};
}

long peakResidentKiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

}  // namespace

TEST_CASE("loadTriangleMesh triangulates an OBJ cube and joins its vertices", "[mesh]") {
  const TempFile obj("cube.obj", kCubeObj);
  const TriangleMesh mesh = loadTriangleMesh(obj.path());
  REQUIRE(mesh.triangles.size() == 12);
  REQUIRE(mesh.vertices.size() == 8);
  for (const glm::dvec3& v : mesh.vertices) {
    CHECK((v.x == 2 || v.x == 3));
    CHECK((v.y == -1 || v.y == 0));
    CHECK((v.z == 5 || v.z == 6));
  }
  for (const auto& triangle : mesh.triangles)
    for (uint32_t index : triangle) CHECK(index < mesh.vertices.size());
}

TEST_CASE("ASCII and binary PLY give the same tetrahedron", "[mesh]") {
  const TempFile ascii("tetra-ascii.ply", asciiTetrahedronPly());
  const TempFile binary("tetra-binary.ply", binaryTetrahedronPly(1.0f));
  const TriangleMesh fromAscii = loadTriangleMesh(ascii.path());
  const TriangleMesh fromBinary = loadTriangleMesh(binary.path());
  CHECK(fromAscii.triangles.size() == 4);
  CHECK(fromBinary.triangles.size() == 4);
  CHECK(vertexSet(fromAscii) == vertexSet(fromBinary));
  CHECK(vertexSet(fromAscii) == vertexSet(kTetrahedron));
}

TEST_CASE("loadTriangleMesh applies nested node transforms", "[mesh]") {
  // glTF: node 0 scales by 2, its child node 1 translates by (10, 0, 0) and holds the triangle.
  std::string positions;
  for (float coordinate : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f})
    appendBytes(positions, coordinate);
  const TempFile bin("triangle.bin", positions);
  const std::string gltf = R"({"asset": {"version": "2.0"}, "scene": 0,
    "scenes": [{"nodes": [0]}],
    "nodes": [{"scale": [2, 2, 2], "children": [1]}, {"translation": [10, 0, 0], "mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "buffers": [{"byteLength": 36, "uri": ")" +
                           std::filesystem::path(bin.path()).filename().string() + R"("}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]}]})";
  const TempFile scene("nodes.gltf", gltf);
  const TriangleMesh mesh = loadTriangleMesh(scene.path());
  REQUIRE(mesh.triangles.size() == 1);
  CHECK(vertexSet(mesh) == vertexSet(TriangleMesh{{{20, 0, 0}, {22, 0, 0}, {20, 2, 0}}, {}}));
}

TEST_CASE("loadTriangleMesh rejects bad files with the file and the problem", "[mesh]") {
  SECTION("missing file") {
    CHECK_THROWS_WITH(loadTriangleMesh("/nonexistent/model.obj"),
                      Contains("cannot open mesh file '/nonexistent/model.obj'"));
  }
  SECTION("unsupported format") {
    const TempFile file("garbage.unknownformat", std::string("\x01\x02\x03 not a mesh"));
    CHECK_THROWS_AS(loadTriangleMesh(file.path()), std::runtime_error);
    CHECK_THROWS_WITH(loadTriangleMesh(file.path()),
                      Contains("cannot read mesh '" + file.path() + "'"));
  }
  SECTION("garbled PLY") {
    std::string ply = binaryTetrahedronPly(1.0f);
    ply.resize(ply.size() - 30);  // cut inside the face list
    const TempFile file("truncated.ply", ply);
    // Counted against the file's size before assimp reads it (which said "cannot read mesh").
    CHECK_THROWS_WITH(loadTriangleMesh(file.path()),
                      Contains("mesh '" + file.path() +
                               "': PLY header declares more data than "
                               "the file holds: 'face' element 2 of the 4 "
                               "declared is cut off"));
  }
  SECTION("no triangles") {
    const TempFile file("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n");
    CHECK_THROWS_WITH(loadTriangleMesh(file.path()),
                      Contains("mesh '" + file.path() + "' has no triangles"));
  }
  SECTION("non-finite coordinate") {
    const TempFile file("nan.ply", binaryTetrahedronPly(std::nanf("")));
    CHECK_THROWS_WITH(loadTriangleMesh(file.path()),
                      Contains("non-finite coordinate") && Contains(file.path()));
  }
}

TEST_CASE("triangleOverlapsBox finds the separating axes", "[mesh]") {
  const glm::dvec3 centre(0.5);
  const glm::dvec3 half(0.5);
  SECTION("box face axes") {
    CHECK(triangleOverlapsBox({{{0.2, 0.2, 0.2}, {0.8, 0.2, 0.2}, {0.2, 0.8, 0.2}}}, centre, half));
    CHECK_FALSE(
        triangleOverlapsBox({{{1.1, 0.2, 0.2}, {1.8, 0.2, 0.2}, {1.1, 0.8, 0.2}}}, centre, half));
  }
  SECTION("touching counts as overlapping") {
    CHECK(triangleOverlapsBox({{{1.0, 0, 0}, {2, 0, 0}, {1.0, 1, 1}}}, centre, half));
    CHECK(triangleOverlapsBox({{{-1, -1, 0}, {3, -1, 0}, {-1, 3, 0}}}, centre, half));
  }
  SECTION("triangle plane axis") {
    // The plane x + y + z = 3.2 passes beyond the corner (1,1,1) while the bounding boxes meet.
    CHECK_FALSE(triangleOverlapsBox({{{3.2, 0, 0}, {0, 3.2, 0}, {0, 0, 3.2}}}, centre, half));
    CHECK(triangleOverlapsBox({{{2.8, 0, 0}, {0, 2.8, 0}, {0, 0, 2.8}}}, centre, half));
  }
  SECTION("edge cross axes") {
    // In the plane z = 0.5, which cuts the box, with bounding boxes overlapping: only the axis
    // across the edge from (2.2,0) to (0,2.2) separates the triangle from the corner (1,1).
    CHECK_FALSE(triangleOverlapsBox({{{2.2, 0, 0.5}, {0, 2.2, 0.5}, {3, 3, 0.5}}}, centre, half));
    CHECK(triangleOverlapsBox({{{1.9, 0, 0.5}, {0, 1.9, 0.5}, {3, 3, 0.5}}}, centre, half));
  }
  SECTION("degenerate triangles act as segments and points") {
    CHECK(triangleOverlapsBox({{{-1, 0.5, 0.5}, {2, 0.5, 0.5}, {2, 0.5, 0.5}}}, centre, half));
    CHECK_FALSE(triangleOverlapsBox({{{2.2, 0, 0.5}, {0, 2.2, 0.5}, {0, 2.2, 0.5}}}, centre, half));
    CHECK(triangleOverlapsBox({{{0.3, 0.3, 0.3}, {0.3, 0.3, 0.3}, {0.3, 0.3, 0.3}}}, centre, half));
  }
}

TEST_CASE("MeshVoxelizer fits the mesh one voxel inside the root cube", "[mesh]") {
  // A 4 x 2 x 1 box from (1, 2, 3): x is the longest extent.
  const TriangleMesh mesh = singleTriangle({1, 2, 3}, {5, 2, 3}, {1, 4, 4});
  const MeshVoxelizer voxelizer(mesh, 4);
  const double voxel = 2.0 / 16;
  CHECK(voxelizer.scale() == Approx((2 - 2 * voxel) / 4));
  auto fitted = [&](const glm::dvec3& p) { return p * voxelizer.scale() + voxelizer.offset(); };
  CHECK(fitted({1, 2, 3}).x == Approx(-1 + voxel));
  CHECK(fitted({5, 2, 3}).x == Approx(1 - voxel));
  CHECK(fitted({3, 3, 3.5}).y == Approx(0).margin(1e-12));  // centred on the bounding box
  CHECK(fitted({3, 3, 3.5}).z == Approx(0).margin(1e-12));
}

TEST_CASE("A voxelized axis-aligned cube is the shell of voxels touching its faces", "[mesh]") {
  const TempFile obj("shell.obj", kCubeObj);
  const int depth = 4;
  const MeshVoxelizer voxelizer(loadTriangleMesh(obj.path()), depth);

  // After the fit the cube is [a, b]^3 with a = -1 + voxel, b = 1 - voxel. A voxel touches its
  // surface when it meets the closed cube without lying inside the open one.
  const double a = -1 + 2.0 / (1 << depth);
  const double b = -a;
  const VoxelSet expected = voxelsWhere(depth, [&](const OctreeNode& voxel) {
    const glm::dvec3 lo = voxel.lower();
    const glm::dvec3 hi = voxel.upper();
    const bool meetsCube = glm::all(glm::lessThanEqual(lo, glm::dvec3(b))) &&
                           glm::all(glm::greaterThanEqual(hi, glm::dvec3(a)));
    const bool insideOpenCube =
        glm::all(glm::greaterThan(lo, glm::dvec3(a))) && glm::all(glm::lessThan(hi, glm::dvec3(b)));
    return meetsCube && !insideOpenCube;
  });
  // The faces lie on grid planes, so the shell is two voxels thick: 16^3 - 12^3.
  REQUIRE(expected.size() == 16 * 16 * 16 - 12 * 12 * 12);

  CHECK(solidVoxels(voxelizer) == expected);
  // Raster order defeats the depth-first cache: the answers must not change.
  CHECK(voxelsWhere(depth, [&](const OctreeNode& voxel) {
          return voxelizer.classify(voxel) == Occupancy::Full;
        }) == expected);
}

TEST_CASE("A single triangle marks only the voxels it overlaps", "[mesh]") {
  // Fitted at depth 3 (voxel 0.25): (-0.75,-0.75,0), (0.75,-0.75,0), (-0.75,0.75,0), i.e. the
  // part of the plane z = 0 with x >= -0.75, y >= -0.75, x + y <= 0.
  const int depth = 3;
  const MeshVoxelizer voxelizer(singleTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}), depth);
  auto at = [&](uint32_t x, uint32_t y, uint32_t z) {
    return voxelizer.classify(OctreeNode{depth, x, y, z});
  };
  CHECK(at(3, 3, 4) == Occupancy::Full);   // x, y in [-0.25, 0], z in [0, 0.25]: interior
  CHECK(at(3, 3, 3) == Occupancy::Full);   // z in [-0.25, 0] touches the plane
  CHECK(at(3, 3, 2) == Occupancy::Empty);  // z in [-0.5, -0.25]
  CHECK(at(6, 1, 4) == Occupancy::Full);   // x in [0.5, 0.75], y in [-0.75, -0.5]
  CHECK(at(1, 6, 4) == Occupancy::Full);
  CHECK(at(5, 4, 4) == Occupancy::Empty);  // x + y >= 0.25: beyond the hypotenuse
  CHECK(at(3, 6, 4) == Occupancy::Empty);

  // The whole grid against the triangle's own separating axes in the plane: x, y and x + y.
  const VoxelSet expected = voxelsWhere(depth, [](const OctreeNode& voxel) {
    const glm::dvec3 lo = voxel.lower();
    const glm::dvec3 hi = voxel.upper();
    return lo.z <= 0 && hi.z >= 0 && lo.x <= 0.75 && hi.x >= -0.75 && lo.y <= 0.75 &&
           hi.y >= -0.75 && lo.x + lo.y <= 0 && hi.x + hi.y >= -1.5;
  });
  CHECK(solidVoxels(voxelizer) == expected);
}

TEST_CASE("MeshVoxelizer never answers Mixed for a voxel and leaves the inside empty", "[mesh]") {
  const int depth = 5;
  const MeshVoxelizer voxelizer(kTetrahedron, depth);
  const VoxelSet surface = voxelsWhere(depth, [&](const OctreeNode& voxel) {
    const Occupancy occupancy = voxelizer.classify(voxel);
    REQUIRE(occupancy != Occupancy::Mixed);
    return occupancy == Occupancy::Full;
  });
  CHECK(surface == solidVoxels(voxelizer));
  // The tetrahedron is centred on its bounding box: the voxels around the centre are inside it.
  CHECK(voxelizer.classify(OctreeNode{depth, 15, 15, 15}) == Occupancy::Empty);
  CHECK(voxelizer.classify(OctreeNode{depth, 16, 16, 16}) == Occupancy::Empty);
  CHECK(voxelizer.classify(OctreeNode{1, 0, 0, 0}) == Occupancy::Mixed);
}

TEST_CASE("A depth-12 voxelization builds in bounded memory and hits the right voxels", "[mesh]") {
  // A needle: {(t, 0.9 t, z) : t in [0, 1], 0.8 t <= z <= 0.8005 t}. Fitted, x spans the cube and
  // the needle widens to about two voxels in z. Within one x-slab of any level it meets at most 2
  // cells in y and 3 in z above the voxels, so at most 6 * 2^L mixed nodes at level L. At levels
  // up to 10 each of the 2^L slabs holds one (too thin to fill a node of 4^3 voxels); at level 11
  // some 2^3 nodes may be all solid and collapse into leaves.
  const int depth = 12;
  const MeshVoxelizer voxelizer(singleTriangle({0, 0, 0}, {1, 0.9, 0.8}, {1, 0.9, 0.8005}), depth);
  const SvoBuild build = buildSvo(voxelizer);
  INFO(build.stats.describe());
  CHECK(build.stats.depth == depth);
  CHECK(build.stats.descriptors >= (1u << 11) - 1);
  CHECK(build.stats.descriptors <= 6 * ((1u << 12) - 1));
  CHECK(build.stats.leaves >= (1u << 11));  // a leaf per 2 of the 4094 x-slabs at least
  // A dense bit grid alone would take 8 GiB.
  CHECK(peakResidentKiB() < 1024 * 1024);

  // The needle meets a box [lo, hi] (mesh coordinates) when some t satisfies all these bounds;
  // `slack` widens (> 0) or narrows (< 0) the test to stay clear of rounding at touching boxes.
  auto meets = [&](const OctreeNode& voxel, double slack) {
    const glm::dvec3 lo = (voxel.lower() - voxelizer.offset()) / voxelizer.scale();
    const glm::dvec3 hi = (voxel.upper() - voxelizer.offset()) / voxelizer.scale();
    const double tLow = std::max({0.0, lo.x, lo.y / 0.9, lo.z / 0.8005});
    const double tHigh = std::min({1.0, hi.x, hi.y / 0.9, hi.z / 0.8});
    return tLow <= tHigh + slack;
  };
  const VoxelSet solid = solidVoxels(voxelizer);
  for (const auto& [x, y, z] : solid) REQUIRE(meets(OctreeNode{depth, x, y, z}, 1e-9));

  // Every voxel the needle clearly meets is solid. In column x only cells near the needle can be
  // (the one-voxel margin keeps these ranges inside the grid).
  const double voxelSize = 2.0 / (1 << depth);
  auto cellOf = [&](double meshCoordinate, int axis) {
    const double fitted = meshCoordinate * voxelizer.scale() + voxelizer.offset()[axis];
    return static_cast<int>(std::floor((fitted + 1) / voxelSize));
  };
  auto meshX = [&](double fitted) { return (fitted - voxelizer.offset().x) / voxelizer.scale(); };
  for (uint32_t x = 0; x < (1u << depth); ++x) {
    const OctreeNode column{depth, x, 0, 0};
    const double t0 = std::clamp(meshX(column.lower().x), 0.0, 1.0);
    const double t1 = std::clamp(meshX(column.upper().x), 0.0, 1.0);
    for (int y = cellOf(0.9 * t0, 1) - 1; y <= cellOf(0.9 * t1, 1) + 1; ++y)
      for (int z = cellOf(0.8 * t0, 2) - 1; z <= cellOf(0.8005 * t1, 2) + 1; ++z) {
        const OctreeNode voxel{depth, x, static_cast<uint32_t>(y), static_cast<uint32_t>(z)};
        if (meets(voxel, -1e-9)) REQUIRE(solid.count({voxel.x, voxel.y, voxel.z}) == 1);
      }
  }
}

TEST_CASE("MeshVoxelizer rejects bad parameters", "[mesh]") {
  const TriangleMesh triangle = singleTriangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  CHECK_THROWS_AS(MeshVoxelizer(triangle, 1), std::invalid_argument);
  CHECK_THROWS_WITH(MeshVoxelizer(triangle, kMaxSvoDepth + 1),
                    Contains("depth must be 2 to 16, got 17"));
  CHECK_THROWS_WITH(MeshVoxelizer(TriangleMesh{}, 4), Contains("no triangles"));
  CHECK_THROWS_WITH(MeshVoxelizer(TriangleMesh{{{0, 0, 0}}, {{0, 0, 1}}}, 4),
                    Contains("triangle 0 uses vertex 1 of 1"));
  CHECK_THROWS_WITH(MeshVoxelizer(singleTriangle({1, 1, 1}, {1, 1, 1}, {1, 1, 1}), 4),
                    Contains("at one point"));
  CHECK_THROWS_WITH(MeshVoxelizer(singleTriangle({0, 0, 0}, {1, 0, 0}, {0, NAN, 0}), 4),
                    Contains("vertex 2 has a non-finite coordinate"));
  const MeshVoxelizer voxelizer(triangle, 4);
  CHECK_THROWS_AS(voxelizer.classify(OctreeNode{5, 0, 0, 0}), std::invalid_argument);
}
