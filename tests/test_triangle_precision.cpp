// The triangle formats' precision study (explore/triangle_precision.h): hand-derived cases of a
// false hit and a hole, the counts' consistency on a real mesh, the sweep's rows, the stress
// triangle and the secondary rays' offset.
#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "bvh_meshes.h"
#include "explore/triangle_precision.h"

namespace rtu {
namespace {

TriangleFormatSpec fixedSpec(FixedTriangleFormat format) {
  TriangleFormatSpec spec;
  spec.fixed = format;
  return spec;
}

TriangleFormatSpec floatSpec(TriangleArithmetic arithmetic) {
  TriangleFormatSpec spec;
  spec.arithmetic = arithmetic;
  return spec;
}

// A triangle far away at the corner (N, N, N) makes the box [0, N]^3, so with N = 2^n - 1 the
// grid's scale is 1 and every integer vertex is its own grid point.
void addCornerTriangle(TriangleMesh& mesh, double N) {
  const auto first = static_cast<uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back({N, N, N});
  mesh.vertices.push_back({N - 1, N, N});
  mesh.vertices.push_back({N, N - 1, N});
  mesh.triangles.push_back({first, first + 1, first + 2});
}

const Ray kDown{{1, 5, 10}, {0, 0, -1}};

}  // namespace

TEST_CASE("A clamped edge makes a false hit: the thin triangle grows to the clamp", "[precision]") {
  // n = 4: the box [0, 15]^3 at scale 1. Triangle 0 is (0,0,0), (15,0,0), (0,1,0): normal
  // (0, 0, 15), r = z, p = x, q = y, e1p = 15 / 15 = 1, e2q = 1 / 15. With E = 10, e1p leaves
  // (-2^-10, 2^-10) and is clamped to 2^-10 - 2^-41. The ray down from (1, 5, 10) meets z = 0 at
  // (1, 5), outside the triangle (x/15 + y = 5.07 > 1), so float64 misses; the kernel's
  // u = e1p kq = 5 (2^-10 - 2^-41), v = e2q kp = 1/15, u + v = 0.0716 <= 1: a hit at t = 10.
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {15, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  addCornerTriangle(mesh, 15);
  const TrianglePrecisionStudy study(mesh, {kDown}, {});
  FixedTriangleFormat format = kC99Format;
  format.n = 4;
  const TriangleFormatPrecision clamped = study.measure(fixedSpec(format));
  CHECK(clamped.counts.rays == 1);
  CHECK(clamped.counts.referenceHits == 0);
  CHECK(clamped.counts.falseHits == 1);
  CHECK(clamped.clamped == 2);  // and the corner triangle: its edges are 1 / 1
  // E = 0: the edges fit (-1, 1) (e1p = 1 - 2^-31), u + v = 5.07 > 1: no hit.
  format.E = 0;
  const TriangleFormatPrecision wide = study.measure(fixedSpec(format));
  CHECK(wide.counts.falseHits == 0);
  CHECK(wide.counts.hits == 0);
  for (const auto a : {TriangleArithmetic::MollerTrumbore32, TriangleArithmetic::Watertight32,
                       TriangleArithmetic::UnitTriangle})
    CHECK(study.measure(floatSpec(a)).counts.falseHits == 0);
}

TEST_CASE("A ray through a shared edge: the VHDL listing's strict u + v < 1 leaves a hole",
          "[precision]") {
  // The square [0, L]^2 in z = 0, L = 1536 = 3 2^9, split along x + y = L: A = (0,0,0), (L,0,0),
  // (0,L,0) and B = (L,L,0), (0,L,0), (L,0,0). Both have n_r = L^2 and edges +-1/L, within
  // (-2^-E, 2^-E) for E = 10; at m = 31 their codes are 2^40 / L = 2^31 / 3 rounded, up since
  // 2^31 = 2 mod 3: code = (2^31 + 1) / 3. On the shared edge u + v = code L / 2^40 for both
  // (A: code (kp + kq), B: code (2L - kp - kq) from its corner) = 1 + 2^-31. The C99 kernel
  // accepts up to (u + v) >> E <= 2^(m-1), i.e. 2^40 + 2^9 >> 10 = 2^30: a hit; the VHDL listing
  // needs u + v < 2^40 and misses both. n = 29 (m = n + 2), the box [0, 2^29 - 1]^3 at scale 1,
  // the ray straight down through (512, 1024), a grid point of the edge.
  TriangleMesh mesh;
  const double L = 1536;
  mesh.vertices = {{0, 0, 0}, {L, 0, 0}, {0, L, 0}, {L, L, 0}};
  mesh.triangles = {{0, 1, 2}, {3, 2, 1}};
  addCornerTriangle(mesh, std::ldexp(1.0, 29) - 1);
  const Ray onEdge{{512, 1024, 5}, {0, 0, -1}};
  // The ray once as a traced ray and once as aimed at the edge (1, 2).
  const TrianglePrecisionStudy study(mesh, {onEdge}, {AimedRay{onEdge, 1, 2}});
  const FixedTriangleFormat vhdlFormat{29, 31, 10, 0, 16, FixedListing::Vhdl};
  const TriangleFormatPrecision vhdl = study.measure(fixedSpec(vhdlFormat));
  CHECK(vhdl.counts.referenceHits == 1);
  CHECK(vhdl.counts.edgeRays == 1);
  CHECK(vhdl.counts.missedHits == 1);
  CHECK(vhdl.counts.holes == 1);
  FixedTriangleFormat c99 = vhdlFormat;
  c99.listing = FixedListing::C99;
  const TriangleFormatPrecision tolerant = study.measure(fixedSpec(c99));
  CHECK(tolerant.counts.holes == 0);
  CHECK(tolerant.counts.edgeRays == 1);
  CHECK(tolerant.counts.sameTriangle + tolerant.counts.otherTriangle == 1);
  CHECK(tolerant.counts.tErrorMax == 0);  // t = 5 exactly
  // The watertight float32 test decides a shared edge once for both triangles.
  CHECK(study.measure(floatSpec(TriangleArithmetic::Watertight32)).counts.holes == 0);
}

TEST_CASE("Precision counts are consistent on a real mesh", "[precision]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  TriangleRaySettings settings;
  settings.views = 2;
  settings.viewSize = 16;
  settings.randomRays = 200;
  settings.aimedRays = 400;
  const TrianglePrecisionStudy study(mesh, settings);
  REQUIRE(study.rays() == 2 * 256 + 200 + 400);
  const uint64_t traced = 2 * 256 + 200;  // the aimed rays count only as edge rays
  // The oracle against itself: nothing differs, no hole.
  const TriangleRayCounts self = study.count([&mesh](const Ray& ray) -> std::optional<FormatHit> {
    const auto hit = closestHit(mesh, ray, 0, INFINITY);
    if (!hit) return std::nullopt;
    return FormatHit{hit->t, hit->triangle};
  });
  CHECK(self.falseHits + self.missedHits + self.otherTriangle + self.holes == 0);
  CHECK(self.tErrorMax == 0);
  CHECK(self.edgeRays > 0);
  FixedTriangleFormat coarse = kC99Format;
  coarse.n = 12;
  for (const TriangleFormatSpec& spec :
       {fixedSpec(kC99Format), fixedSpec(coarse), fixedSpec(kVhdlFormat),
        floatSpec(TriangleArithmetic::UnitTriangle), floatSpec(TriangleArithmetic::Watertight32),
        floatSpec(TriangleArithmetic::MollerTrumbore32)}) {
    const TriangleRayCounts c = study.measure(spec).counts;
    INFO(spec.name());
    CHECK(c.rays == traced);
    CHECK(c.referenceHits == self.referenceHits);
    // Every reference hit is missed, on another triangle or on the same; every hit likewise.
    CHECK(c.referenceHits == c.missedHits + c.otherTriangle + c.sameTriangle);
    CHECK(c.hits == c.falseHits + c.otherTriangle + c.sameTriangle);
    CHECK(c.otherNotAdjacent <= c.otherTriangle);
    CHECK(c.edgeRays == self.edgeRays);
    CHECK(c.holes <= c.edgeRays);
    CHECK(c.tErrorMean() <= c.tErrorMax);
    CHECK(c.sameTriangle > 0);
  }
  // Fewer grid bits, larger t errors.
  CHECK(study.measure(fixedSpec(coarse)).counts.tErrorMax >
        study.measure(fixedSpec(kC99Format)).counts.tErrorMax);
}

TEST_CASE("Secondary rays offset by 2 grid units do not hit their own triangle", "[precision]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  TriangleRaySettings settings;
  settings.views = 2;
  settings.viewSize = 24;
  settings.randomRays = 0;
  settings.aimedRays = 0;
  const TrianglePrecisionStudy study(mesh, settings);
  const TriangleFormatPrecision p = study.measure(fixedSpec(kC99Format));
  REQUIRE(p.self);
  CHECK(p.self->secondaryRays == p.counts.hits);
  CHECK(p.self->selfHitsOffset == 0);
  CHECK(p.self->selfHitsNoOffset > 0);
  CHECK_FALSE(study.measure(floatSpec(TriangleArithmetic::Watertight32)).self);
}

TEST_CASE("The sweep varies one parameter at a time from the C99 prototype", "[precision]") {
  TriangleSweep sweep;
  sweep.n = {16, 29};
  sweep.C = {8};
  const std::vector<TriangleFormatSpec> rows = sweepRows(sweep);
  REQUIRE(rows.size() == 8);
  CHECK(rows[0].name() == "c99 n=29 m=32 E=10 T=0 C=16");
  CHECK(rows[0].swept.empty());
  CHECK(rows[1].name() == "c99 n=16 m=32 E=10 T=0 C=16");  // n = 29 is the prototype: once
  CHECK(rows[1].swept == "n");
  CHECK(rows[2].name() == "c99 n=29 m=32 E=10 T=0 C=8");
  CHECK(rows[3].name() == "vhdl n=30 m=32 E=10 T=0 C=16");
  CHECK(rows[4].name() == "binary32 unit-triangle (ieee division)");
  CHECK(rows[5].name() == "binary32 unit-triangle (truncating division)");
  CHECK(rows[6].name() == "float32 moller-trumbore");
  CHECK(rows[7].name() == "float32 watertight");
  CHECK(rows[7].structure() == "all triangles");
  CHECK(rows[0].structure() == "bih");
  sweep.m = {40};
  CHECK_THROWS_WITH(sweepRows(sweep), Catch::Contains("m must be in [2, 32], is 40"));
}

TEST_CASE("The stress triangle spans the box's diagonal and is as wide as asked", "[precision]") {
  const TriangleMesh stress = stressTriangle(0.01);
  REQUIRE(stress.triangles.size() == 1);
  const Aabb<double> box = meshBounds(stress);
  CHECK(box.lower == glm::dvec3(0, 0, 0));
  CHECK(box.upper == glm::dvec3(1, 1, 1));
  // The third vertex's distance from the diagonal (1, 1, 1)/sqrt 3 through the origin.
  const glm::dvec3 c = stress.vertices[2];
  const double along = (c.x + c.y + c.z) / std::sqrt(3.0);
  CHECK(std::sqrt(glm::dot(c, c) - along * along) == Approx(0.01).epsilon(1e-12));
  // Its plane is x + y = 2z (normal (1, 1, -2)); a ray down onto the point halfway between the
  // box's centre and the third vertex hits it in float64 and in every format.
  const double side = 0.01 / std::sqrt(2.0);
  const Ray middle{{0.5 + side / 2, 0.5 - side / 2, 3}, {0, 0, -1}};
  const TrianglePrecisionStudy study(stress, {middle}, {});
  for (const TriangleFormatSpec& spec : sweepRows({})) {
    INFO(spec.name());
    CHECK(study.measure(spec).counts.sameTriangle == 1);
  }
}

}  // namespace rtu
