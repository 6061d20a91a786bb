// Issue 11, section 3: the extremes of the fixed-point traversal, each with the outcome the
// hardware (golden model, bit-exact with the RTL) gives against the float64 reference and against
// geometry. Expected values come from the scene's geometry, worked out in the comments.
// docs/precision.md "The extremes" describes each case.

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <limits>

#include "inputs/host_buffers.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/ray_transform.h"
#include "kinds/svo/reference_model.h"
#include "kinds/svo/result_summary.h"
#include "kinds/svo/svo_builder.h"

namespace rtu {
namespace {

const FixedFormat kThesis{32, 16};

// Solid where the voxel centre satisfies `solid`, on a 2^depth grid.
class Cells : public VoxelSource {
 public:
  Cells(int depth, std::function<bool(const glm::dvec3&)> solid)
      : depth_(depth), solid_(std::move(solid)) {}
  int depth() const override { return depth_; }
  Occupancy classify(const OctreeNode& node) const override {
    if (node.level < depth_) return Occupancy::Mixed;
    return solid_(node.centre()) ? Occupancy::Full : Occupancy::Empty;
  }

 private:
  int depth_;
  std::function<bool(const glm::dvec3&)> solid_;
};

// A depth-3 grid (voxels 0.25 wide) solid in the column of cells whose centres lie within 0.1
// of `across` on the two axes other than `axis`, along the whole of `axis`.
SvoBuild column(int axis, glm::dvec2 across) {
  return buildSvo(Cells(3, [axis, across](const glm::dvec3& c) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    return std::abs(c[u] - across.x) < 0.1 && std::abs(c[v] - across.y) < 0.1;
  }));
}

struct Outcome {
  TraversalResult fixed;
  ReferenceResult exact;
  double t() const { return kThesis.toDouble(fixed.tHit); }
};

Outcome trace(const SvoBuild& build, const Ray& ray, FixedFormat format = kThesis) {
  GoldenModel golden(build.image.memory(),
                     GoldenConfig{format, FloatConversion::Rtl, kMaxStackFrames});
  ReferenceModel reference(build.image.memory());
  return {golden.trace(makeTValueRecord(0, ray, build.image.root)),
          reference.trace(ray, build.image.root)};
}

// A ray along +-`axis` (direction component `sign`) from 3 units outside the cube, at (0.6, 0.1) on
// the other two axes, with `tilt` as the next axis' direction component.
Ray axisRay(int axis, double sign, double tilt) {
  glm::dvec3 origin(0.0), direction(0.0);
  origin[axis] = -3.0 * sign;
  origin[(axis + 1) % 3] = 0.6;
  origin[(axis + 2) % 3] = 0.1;
  direction[axis] = sign;
  direction[(axis + 1) % 3] = tilt;
  return {origin, direction};
}

}  // namespace

TEST_CASE("Exact zero direction components: tilted by epsilon, the ray hits where geometry says",
          "[precision][extremes]") {
  // The column holding (0.6, 0.1) across the ray: the ray enters the cube after 2 units, through
  // the face across its axis, into the column's first voxel. Epsilon (1e-4) moves it by at most
  // 5e-4 inside the cube, far from the column's sides (0.1 away).
  for (int axis = 0; axis < 3; ++axis) {
    const SvoBuild build = column(axis, {0.625, 0.125});
    for (double sign : {1.0, -1.0}) {
      for (double zero : {0.0, -0.0}) {
        INFO("axis " << axis << " sign " << sign << " zero " << zero);
        const Outcome o = trace(build, axisRay(axis, sign, zero));
        REQUIRE(o.fixed.hit);
        CHECK(std::abs(o.t() - 2.0) <= 2.0 / 65536);
        CHECK(o.fixed.normal[axis] == kThesis.one());
        CHECK_FALSE(o.fixed.tOverflow);
        REQUIRE(o.exact.hit);
        CHECK(std::abs(o.exact.tHit - 2.0) < 1e-9);
      }
    }
  }
}

TEST_CASE("A direction component too small for the range loses the ray's position: flagged",
          "[precision][extremes]") {
  // For a ray at 0.6 on an axis whose direction component is d, the t-values on that axis are
  // (-1 - 0.6) / d and (1 - 0.6) / d. Once 1.6 / d exceeds the range (32768 in Q16.16, so
  // d < 4.88e-5), t0 saturates; from one float step above zero (1.4e-45) on, both do. The midpoints
  // then place the ray just above the axis' centre plane, not at 0.6: the column at 0.6 is missed
  // (leaky) and one just above 0 is hit (conservative). float64 has the range and is right.
  // One float step needs a largest component in [0.5, 1), which the set-up's power-of-two scaling
  // leaves alone (next to a 1 it halves the step to 0, and the ray counts as parallel).
  const double oneStep = std::numeric_limits<float>::denorm_min();
  for (int axis = 0; axis < 3; ++axis) {
    const int across = (axis + 1) % 3;
    const SvoBuild atPosition = column(axis, {0.625, 0.125});
    for (double sign : {1.0, -1.0}) {
      // Mirrored space: a negative component puts the ray at -0.6 and "just above the centre"
      // at just below 0 in the world.
      const SvoBuild nearCentre = column(axis, {0.125 * sign, 0.125});
      for (double d : {oneStep, 1e-30, 1e-7}) {
        INFO("axis " << axis << " sign " << sign << " d " << d);
        const Ray ray = axisRay(axis, d == oneStep ? 0.75 : 1.0, sign * d);
        const Outcome real = trace(atPosition, ray);
        CHECK_FALSE(real.fixed.hit);
        CHECK(real.fixed.tOverflow);
        CHECK(real.exact.hit);
        Ray shifted = ray;
        shifted.origin[across] = 0.6 * sign;
        const Outcome ghost = trace(nearCentre, shifted);
        CHECK(ghost.fixed.hit);
        CHECK(ghost.fixed.tOverflow);
        CHECK_FALSE(ghost.exact.hit);
      }
      // Just inside the range (t0 = -1.6 / 5.2e-5 = -30769): right, and not flagged.
      const Outcome inRange = trace(atPosition, axisRay(axis, 1.0, sign * 5.2e-5));
      CHECK(inRange.fixed.hit);
      CHECK_FALSE(inRange.fixed.tOverflow);
      // Only t0 saturates at d = 4.6e-5 (-34783 -> -32768, t1 = 8696): the midpoints place the
      // ray at -1 + 2 * 32768 / (32768 + 8696) = 0.581 instead of 0.6, in the same cell. Flagged
      // all the same, as the error grows with the part cut off.
      const Outcome oneEnd = trace(atPosition, axisRay(axis, 1.0, sign * 4.6e-5));
      CHECK(oneEnd.fixed.hit);
      CHECK(oneEnd.fixed.tOverflow);
      // Q24.24 has the range (+-8.4e6) for d = 1e-5 (t0 = -1.6e5): right again.
      const Outcome wide = trace(atPosition, axisRay(axis, 1.0, sign * 1e-5), FixedFormat{48, 24});
      CHECK(wide.fixed.hit);
      CHECK_FALSE(wide.fixed.tOverflow);
    }
  }
}

TEST_CASE("Ray records count components below epsilon times the largest as zero",
          "[precision][extremes]") {
  // The job manager's set-up (ray_transform.h) replaces a one-step component by tau = 1e-4, so
  // the record of a nearly axis-parallel ray gives the job of an exactly parallel one.
  ModelHeader identity;
  RayRecord parallel;
  parallel.origin = {0.6f, 0.1f, -3.0f};
  parallel.direction = {0.0f, 0.0f, 1.0f};
  RayRecord oneStep = parallel;
  oneStep.direction[0] = std::numeric_limits<float>::denorm_min();
  const TValueRecord a = rayRecordToJob(parallel, identity);
  const TValueRecord b = rayRecordToJob(oneStep, identity);
  CHECK(a.t0Bits == b.t0Bits);
  CHECK(a.t1Bits == b.t1Bits);
  CHECK(bitsToFloat(b.t0Bits[0]) == Approx(-1.6f / 1e-4f));
}

TEST_CASE("All direction components tiny or huge: the same ray as a unit direction",
          "[precision][extremes]") {
  // From (-3,-3,-3) towards the centre of the radius-0.8 sphere: it meets the surface after
  // 3 sqrt(3) - 0.8 = 4.396 units, within a voxel diagonal (sqrt(3) 2/64) on the voxel grid.
  // Before the set-up scaled the direction, 1e-30 underflowed (every ray missed, leaky) and 1e30
  // overflowed (every component became epsilon, flagged).
  const SvoBuild sphere = buildSvo(*makeProceduralScene("sphere", 6));
  const glm::dvec3 origin(-3.0);
  const Outcome unit = trace(sphere, Ray{origin, glm::dvec3(1.0, 1.0, 1.0)});
  REQUIRE(unit.fixed.hit);
  CHECK(std::abs(unit.t() - (3.0 * std::sqrt(3.0) - 0.8)) < std::sqrt(3.0) * 2.0 / 64);
  for (double scale : {0x1p-120, 0x1p-60, 0x1p60, 0x1p120}) {
    INFO("scale " << scale);
    const Outcome o = trace(sphere, Ray{origin, glm::dvec3(scale)});
    CHECK(o.fixed == unit.fixed);  // powers of two scale exactly: the same job
  }
  for (double scale : {1e-30, 1e-45, 1e30}) {
    INFO("scale " << scale);
    const Outcome o = trace(sphere, Ray{origin, glm::dvec3(scale)});
    CHECK(o.fixed.hit);
    CHECK(std::abs(o.t() - unit.t()) <= 2.0 / 65536);
    CHECK_FALSE(o.fixed.tOverflow);
  }
}

TEST_CASE("NaN, infinite and zero directions are errors, never an answer",
          "[precision][extremes]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(makeTValueRecord(0, Ray{{0, 0, -3}, {nan, 0, 1}}, 0),
                    Catch::Contains("finite"));
  CHECK_THROWS_WITH(makeTValueRecord(0, Ray{{inf, 0, -3}, {0, 0, 1}}, 0),
                    Catch::Contains("finite"));
  CHECK_THROWS_WITH(makeTValueRecord(0, Ray{{0, 0, -3}, {0, 0, 0}}, 0), Catch::Contains("zero"));
  // Job records may carry infinite t-values (a parallel ray from a driver without epsilon):
  // t0 = -inf, t1 = +inf on x saturate, the ray's x is lost, and the result is flagged.
  TValueRecord job = makeTValueRecord(0, Ray{{0.6, 0.1, -3}, {0, 0, 1}}, 0);
  job.t0Bits[0] = floatBits(-std::numeric_limits<float>::infinity());
  job.t1Bits[0] = floatBits(std::numeric_limits<float>::infinity());
  const std::vector<TValueRecord> decoded = decodeJobRecords(encodeJobRecords({job}));
  const SvoBuild build = column(2, {0.625, 0.125});
  const TraversalResult result =
      GoldenModel(build.image.memory(), GoldenConfig{}).trace(decoded[0]);
  CHECK(result.tOverflow);
  CHECK_FALSE(result.hit);  // the column at x = 0.6 is missed: the ray runs at x = 0+
}

}  // namespace rtu

namespace rtu {
namespace {

// One leaf at `depth`, reached through one child per level (slots cycling through `kSlots`): a
// hand-made image, as the builder stops at depth 16. Descriptor l sits at word l, its only child's
// descriptor right after it.
const int kSlots[] = {6, 1, 3, 4, 2, 5, 0, 7};

std::vector<uint32_t> deepChain(int depth, glm::dvec3& lower, double& size) {
  std::vector<uint32_t> words;
  lower = glm::dvec3(-1.0);
  size = 2.0;
  for (int level = 0; level < depth; ++level) {
    const int slot = kSlots[level % 8];
    const auto bit = static_cast<uint8_t>(1u << slot);
    words.push_back(Descriptor::make(false, 1, bit, level == depth - 1 ? bit : 0).word);
    size /= 2;
    for (int k = 0; k < 3; ++k)
      if (slot >> k & 1) lower[k] += size;
  }
  return words;
}

struct DeepCount {
  int rays = 0, hits = 0, referenceHits = 0, flagged = 0;
};

// 8x8 rays from (0.3, 0.2, -3) to points spread over the deep leaf's middle.
DeepCount traceDeep(int depth, FixedFormat format) {
  glm::dvec3 lower;
  double size = 0;
  const std::vector<uint32_t> words = deepChain(depth, lower, size);
  const WordMemory memory(words);
  GoldenModel golden(memory, GoldenConfig{format, FloatConversion::Rtl, kMaxStackFrames});
  ReferenceModel reference(memory);
  DeepCount count;
  const glm::dvec3 eye(0.3, 0.2, -3.0);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const glm::dvec3 target = lower + size * glm::dvec3((i + 0.5) / 8, (j + 0.5) / 8, 0.5);
      const Ray ray{eye, target - eye};
      const TraversalResult fixed = golden.trace(makeTValueRecord(0, ray, 0));
      ++count.rays;
      count.hits += fixed.hit;
      count.flagged += fixed.belowResolution;
      count.referenceHits += reference.trace(ray, 0).hit;
    }
  return count;
}

}  // namespace

TEST_CASE("Trees deeper than the fraction bits: the leaf is missed, and the rays are flagged",
          "[precision][extremes]") {
  // A node at level L is 2^(1-L) wide; along the ray's steepest axis (|d| about 0.96 here) its
  // t-extent is about 2^(1-L) / 0.96. With F fraction bits its children are under a step wide
  // once that is below 2^(1-F): from L = F + 1 on, so leaves at depth F + 2 and deeper are
  // flagged. Where the extent is a step or less, the truncated midpoints make the ray pass the
  // tiny leaf: missed hits (leaky). float64 hits it at every depth.
  for (const FixedFormat format : {FixedFormat{24, 12}, kThesis}) {
    const int f = format.fractionBits;
    INFO(format.describe());
    const DeepCount resolved = traceDeep(f + 1, format);
    CHECK(resolved.referenceHits == resolved.rays);
    CHECK(resolved.hits == resolved.rays);
    CHECK(resolved.flagged == 0);
    CHECK(traceDeep(f + 2, format).flagged == 64);
    const DeepCount beyond = traceDeep(f + 3, format);
    CHECK(beyond.flagged == beyond.rays);
    CHECK(beyond.hits < beyond.rays);
    const DeepCount far = traceDeep(f + 5, format);
    CHECK(far.referenceHits == far.rays);
    CHECK(far.hits == 0);
    CHECK(far.flagged == far.rays);
  }
  // With 24 fraction bits or more the float32 job is the limit: t about 3.3 carries 2^-22, so a
  // leaf at depth 23 (2^-22 wide) is already hit by only some rays, and by none at depth 28,
  // without any flag: the one silent case left (docs/precision.md).
  const DeepCount float32Limit = traceDeep(28, FixedFormat{48, 32});
  CHECK(float32Limit.referenceHits == float32Limit.rays);
  CHECK(float32Limit.hits == 0);
  CHECK(float32Limit.flagged == 0);
  CHECK(traceDeep(22, FixedFormat{48, 32}).hits == 64);
}

TEST_CASE("A camera inside the volume reports the first voxel from where the line enters the cube",
          "[precision][extremes]") {
  // The traversal starts where the ray's line enters the root cube, also behind the origin: from
  // inside a closed surface it reports the surface behind the camera, at t < 0. Along +z from
  // (0.01, 0.02, 0.03) the line enters at z = -1 and meets the sphere (radius 0.8) at
  // z = -sqrt(0.64 - 0.0005) = -0.7997: t = -0.8297, within a voxel (2/64) on the grid.
  // float64 does the same: the algorithm's behaviour, not the format's. Counted and warned.
  const glm::dvec3 inside(0.01, 0.02, 0.03);
  for (const char* scene : {"shell", "sphere"}) {  // an empty voxel, a solid voxel
    INFO(scene);
    const SvoBuild build = buildSvo(*makeProceduralScene(scene, 6));
    const Outcome o = trace(build, Ray{inside, {0.0, 0.0, 1.0}});
    REQUIRE(o.fixed.hit);
    CHECK(std::abs(o.t() - (-0.03 - std::sqrt(0.64 - 0.0005))) < 2.0 / 64);
    CHECK(o.exact.hit);
    CHECK(std::abs(o.exact.tHit - o.t()) < 4.0 / 65536);
    const ResultSummary summary = ResultSummary::of({o.fixed});
    CHECK(summary.hitsBehindOrigin == 1);
    CHECK_THAT(summary.describe(), Catch::Contains("behind the ray origin"));
  }
  // On the face z = -1 of the root cube, looking in: t0z = 0, and the sphere at z = -0.7921
  // (x = 0.1, y = 0.05) is 0.2079 ahead. Looking out: the line's segment in the cube lies behind,
  // t in [-2, 0], and the first voxel from z = +1 is at t = -(1 + 0.7921).
  const SvoBuild sphere = buildSvo(*makeProceduralScene("sphere", 6));
  const double surface = std::sqrt(0.64 - 0.01 - 0.0025);
  const Outcome in = trace(sphere, Ray{{0.1, 0.05, -1.0}, {0.0, 0.0, 1.0}});
  CHECK(std::abs(in.t() - (1.0 - surface)) < 2.0 / 64);
  const Outcome out = trace(sphere, Ray{{0.1, 0.05, -1.0}, {0.0, 0.0, -1.0}});
  CHECK(std::abs(out.t() + 1.0 + surface) < 2.0 / 64);
  CHECK(in.exact.voxel != out.exact.voxel);
}

TEST_CASE("Rays in shared faces and in the root cube's faces take the side epsilon tilts them to",
          "[precision][extremes]") {
  // An exactly zero component becomes +epsilon after mirroring, so a ray in a plane between two
  // voxels runs into the upper one (for t > 0): both models, and geometry of the tilted ray.
  // Along +z at y = 0.1: in the root's centre plane x = 0, in the level-1 plane x = 0.5, and in
  // the root's faces x = -1 (tilted inwards: hits) and x = +1 (tilted out: t1x = 0, a miss).
  struct Case {
    double x;
    double upperCell, lowerCell;  // centres of the cells on either side
  };
  for (const Case c : {Case{0.0, 0.125, -0.125}, Case{0.5, 0.625, 0.375}}) {
    INFO("plane x = " << c.x);
    const Ray ray{{c.x, 0.1, -3.0}, {0.0, 0.0, 1.0}};
    const Outcome upper = trace(column(2, {c.upperCell, 0.125}), ray);
    CHECK(upper.fixed.hit);
    CHECK(upper.exact.hit);
    CHECK(std::abs(upper.t() - 2.0) <= 2.0 / 65536);
    const Outcome lower = trace(column(2, {c.lowerCell, 0.125}), ray);
    CHECK_FALSE(lower.fixed.hit);
    CHECK_FALSE(lower.exact.hit);
  }
  const Outcome lowFace =
      trace(column(2, {-0.875, 0.125}), Ray{{-1.0, 0.1, -3.0}, {0.0, 0.0, 1.0}});
  CHECK(lowFace.fixed.hit);
  CHECK(lowFace.exact.hit);
  const Outcome highFace = trace(column(2, {0.875, 0.125}), Ray{{1.0, 0.1, -3.0}, {0.0, 0.0, 1.0}});
  CHECK_FALSE(highFace.fixed.hit);
  CHECK_FALSE(highFace.exact.hit);
}

TEST_CASE("Three planes tied: the corner is crossed x first, then y, then z",
          "[precision][extremes]") {
  // From (-3,-3,-3) along (1,1,1) the ray meets the root's three centre planes at the same t,
  // 3 sqrt(3), at the cube's centre, where all eight depth-1 cells touch. Both models break the
  // tie as the RTL's comparisons do (x before y before z) and walk cells 0, 1 (x), 3 (x y),
  // 7: a cell only touched at the corner point is reported hit when it is 1 or 3
  // (conservative), missed when it is 2, 4, 5 or 6.
  const double corner = 3.0 * std::sqrt(3.0);
  for (int slot = 0; slot < 8; ++slot) {
    INFO("solid cell " << slot);
    const SvoBuild build = buildSvo(Cells(1, [slot](const glm::dvec3& c) {
      return (c.x > 0) == (slot & 1) && (c.y > 0) == ((slot & 2) != 0) &&
             (c.z > 0) == ((slot & 4) != 0);
    }));
    const Outcome o = trace(build, Ray{glm::dvec3(-3.0), glm::dvec3(1.0)});
    const bool visited = slot == 0 || slot == 1 || slot == 3 || slot == 7;
    CHECK(o.fixed.hit == visited);
    CHECK(o.exact.hit == visited);
    if (visited) {
      const double t = slot == 0 ? 2.0 * std::sqrt(3.0) : corner;  // entry corner or centre
      CHECK(std::abs(o.t() - t) < 4.0 / 65536);
      CHECK(std::abs(o.exact.tHit - t) < 1e-9);
    }
  }
  // Two planes tied: along (1, 1, 0) at z = -0.5 the ray crosses the x and y centre planes at
  // 3 sqrt(2), on the edge shared by cells 0, 1, 2 and 3 (z lower): x goes first, so cell 1 is
  // reported at the edge (conservative) and cell 2 is not.
  for (int slot : {1, 2}) {
    INFO("solid cell " << slot);
    const SvoBuild build = buildSvo(Cells(1, [slot](const glm::dvec3& c) {
      return (c.x > 0) == (slot & 1) && (c.y > 0) == ((slot & 2) != 0) && c.z < 0;
    }));
    const Outcome o = trace(build, Ray{{-3.0, -3.0, -0.5}, {1.0, 1.0, 0.0}});
    CHECK(o.fixed.hit == (slot == 1));
    CHECK(o.exact.hit == (slot == 1));
    if (slot == 1) CHECK(std::abs(o.t() - 3.0 * std::sqrt(2.0)) < 4.0 / 65536);
  }
}

TEST_CASE("Translation: the same model and rays near the origin and far away",
          "[precision][extremes]") {
  // Ray records are float32 in world space. A model moved by T = 2^20 with a camera moved alike:
  // the record's origin T + o is rounded to 2^-3, so only offsets o on that grid give the same
  // jobs; others move the ray by up to 1/16 and hit other voxels, silently (the record cannot
  // carry more). Camera offsets on the grid: bit for bit the same results.
  const SvoBuild sphere = buildSvo(*makeProceduralScene("sphere", 6));
  GoldenModel golden(sphere.image.memory(), GoldenConfig{});
  ModelHeader near, far;
  const float shift = 0x1p20f;
  far.translation = {shift, -shift, shift};
  size_t different = 0, rays = 0;
  for (const glm::dvec3 offset : {glm::dvec3(0.25, 0.125, -3.0), glm::dvec3(0.3, 0.2, -3.0)}) {
    for (int i = 0; i < 16; ++i)
      for (int j = 0; j < 16; ++j) {
        RayRecord record;
        record.direction = {static_cast<float>(-offset.x + (i - 7.5) * 0.05),
                            static_cast<float>(-offset.y + (j - 7.5) * 0.05), 3.0f};
        RayRecord moved = record;
        for (int k = 0; k < 3; ++k) {
          record.origin[k] = static_cast<float>(offset[k]);
          moved.origin[k] = static_cast<float>(offset[k] + far.translation[k]);
        }
        const TraversalResult a = golden.trace(rayRecordToJob(record, near));
        const TraversalResult b = golden.trace(rayRecordToJob(moved, far));
        if (offset.x == 0.25) {
          CHECK(a == b);
        } else {
          ++rays;
          different += a.hit != b.hit || a.tHit != b.tHit;
        }
      }
  }
  CHECK(rays == 256);
  CHECK(different > 0);  // the ray moved by (0.05, -0.05, 0): hits through x or y faces move
}

}  // namespace rtu
