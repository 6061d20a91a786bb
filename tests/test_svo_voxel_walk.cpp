// The float64 voxel walk (src/kinds/svo/svo_voxel_walk.h), a geometric oracle that shares no
// traversal code, on hand-built images with hand-derived answers, then against the golden model on
// the procedural scenes (issue 26: an independent check of the traversal core's control flow),
// which tests/test_kind_oracles.cpp runs as the SVO kind's oracle.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "inputs/camera.h"
#include "kind_fixture.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/reference_model.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_voxel_walk.h"
#include "svo_descriptor.h"

namespace rtu {
namespace {

constexpr double kStep = 1.0 / 65536.0;  // Q16.16
constexpr int kDepth = 7;                // of the procedural scenes

// Hand-built images: index = word address.
struct VoxelWalkExpected {
  bool hit;
  double t = 0.0;
  int axis = 0;
  int level = 0;
  uint32_t x = 0, y = 0, z = 0;
  uint64_t key = 0;
};

// Checks the oracle against the hand-derived answer, then the golden model against both (so the
// hand derivation is checked too). `direction` is the exact line; it is also given to the golden
// model, whose t is along the normalised direction: the walk gets the same normalised line.
void checkHandCase(const std::vector<uint32_t>& words, uint32_t root, glm::dvec3 origin,
                   glm::dvec3 direction, const VoxelWalkExpected& expected) {
  const WordMemory memory(words);
  const double length =
      std::sqrt(direction.x * direction.x + direction.y * direction.y + direction.z * direction.z);
  const VoxelWalkResult walk = walkVoxels(memory, root, origin, direction);
  INFO("origin " << origin.x << "," << origin.y << "," << origin.z << " direction " << direction.x
                 << "," << direction.y << "," << direction.z);
  REQUIRE(walk.hit == expected.hit);
  if (expected.hit) {
    CHECK(walk.tHit == Approx(expected.t).margin(1e-12));
    CHECK(walk.entryAxis == expected.axis);
    CHECK(walk.level == expected.level);
    CHECK(walk.x == expected.x);
    CHECK(walk.y == expected.y);
    CHECK(walk.z == expected.z);
    CHECK(walk.voxelKey == expected.key);
  }
  // The same line as the job traces: t then scales with 1 / |direction|.
  const VoxelWalkResult unit =
      walkVoxels(memory, root, origin, jobLineDirection(direction, kDefaultDirectionEpsilon));
  GoldenModel golden(memory, GoldenConfig{});
  const TraversalResult fixed = golden.trace(makeTValueRecord(0, Ray{origin, direction}, root));
  REQUIRE(fixed.hit == expected.hit);
  REQUIRE(unit.hit == expected.hit);
  if (expected.hit) {
    CHECK(unit.voxelKey == expected.key);
    CHECK(unit.tHit == Approx(expected.t * length).margin(1e-4));
    CHECK(golden.lastHitVoxel() == expected.key);
    CHECK(GoldenConfig{}.format.toDouble(fixed.tHit) ==
          Approx(expected.t * length).margin(4 * kStep));
  }
}

}  // namespace

TEST_CASE("Voxel walk: a single voxel, hit across an empty octant or missed", "[voxel-walk]") {
  // The root's only child: slot 7, the octant [0,1]^3, a leaf.
  const std::vector<uint32_t> image{descriptor(false, 0, 0x80, 0x80)};
  // Along +x at y = 0.3, z = 0.7: enters the root at x = -1 (t = 2), crosses the empty octant
  // [-1,0]x[0,1]x[0,1] (slot 6) and enters the voxel at x = 0, t = 3, through its x face.
  checkHandCase(image, 0, {-3, 0.3, 0.7}, {1, 0, 0}, {true, 3.0, 0, 1, 1, 1, 1, 7});
  // At y = -0.3 it crosses slots 4 and 5 only: a miss.
  checkHandCase(image, 0, {-3, -0.3, 0.7}, {1, 0, 0}, {false});
  // Along -x from x = 3 it enters the voxel at once through the root's face x = 1, t = 2.
  checkHandCase(image, 0, {3, 0.3, 0.7}, {-1, 0, 0}, {true, 2.0, 0, 1, 1, 1, 1, 7});
  // Along -z from z = 4 at x = 0.5, y = 0.25: enters through z = 1 at t = 3.
  checkHandCase(image, 0, {0.5, 0.25, 4}, {0, 0, -1}, {true, 3.0, 2, 1, 1, 1, 1, 7});
  // A slanted ray: x = -1.5 + t, y = 0.2 + 0.1 t, z = 0.6: root entry x = -1 at t = 0.5, the
  // voxel's x face at t = 1.5 (y = 0.35 there, inside).
  checkHandCase(image, 0, {-1.5, 0.2, 0.6}, {1, 0.1, 0}, {true, 1.5, 0, 1, 1, 1, 1, 7});
  // The diagonal through the centre, a corner of all eight octants: hits at t = 2, the tie on
  // the entry face going to x.
  const VoxelWalkResult diagonal = walkVoxels(WordMemory(image), 0, {-2, -2, -2}, {1, 1, 1});
  CHECK(diagonal.hit);
  CHECK(diagonal.tHit == 2.0);
  CHECK(diagonal.entryAxis == 0);
  CHECK(diagonal.clearance == 0.0);  // it grazes every edge through the centre
}

TEST_CASE("Voxel walk: two levels, through an empty octant into a filled one", "[voxel-walk]") {
  // Root: slot 0 (octant [-1,0]^3) a node, its descriptor at word 1; in it, slot 7 ([-0.5,0]^3)
  // and slot 1 ([-0.5,0]x[-1,-0.5]x[-1,-0.5]) are voxels.
  const std::vector<uint32_t> image{descriptor(false, 1, 0x01, 0x00),
                                    descriptor(false, 0, 0x82, 0x82)};
  // Up z at x = y = -0.25: enters at z = -1 (t = 4) into the empty level-2 cell of slot 3, then
  // the voxel of slot 7 at z = -0.5, t = 4.5.
  checkHandCase(image, 0, {-0.25, -0.25, -5}, {0, 0, 1}, {true, 4.5, 2, 2, 1, 1, 1, 1 << 3 | 7});
  // At y = -0.75 the voxel of slot 1 is there at once.
  checkHandCase(image, 0, {-0.25, -0.75, -5}, {0, 0, 1}, {true, 4.0, 2, 2, 1, 0, 0, 1 << 3 | 1});
  // Down z from z = 5: the empty root octant of slot 4 from z = 1 to 0, then the voxel, entered
  // through its upper z face at t = 5.
  checkHandCase(image, 0, {-0.25, -0.25, 5}, {0, 0, -1}, {true, 5.0, 2, 2, 1, 1, 1, 1 << 3 | 7});
  // At x = 0.25 it stays in the root's empty upper-x octants.
  checkHandCase(image, 0, {0.25, -0.25, 5}, {0, 0, -1}, {false});
  // Along +y at x = -0.75, z = -0.25: through node 0's empty level-2 cells of slots 4 and 6, then
  // the root's empty octant of slot 2: a miss that passes through a node.
  checkHandCase(image, 0, {-0.75, -5, -0.25}, {0, 1, 0}, {false});
}

TEST_CASE("Voxel walk: far pointers, also wrapping to children before their parent",
          "[voxel-walk]") {
  // Root at word 2, far: its pointer 1 names the far word at 3, which holds the offset 4 of the
  // children from the root, word 6. Words 4 and 5 are decoys (a node full of voxels) that a walk
  // misreading the far word would find.
  const uint32_t decoy = descriptor(false, 0, 0xFF, 0xFF);
  const std::vector<uint32_t> image{0,     0,     descriptor(true, 1, 0x01, 0x00), 4,
                                    decoy, decoy, descriptor(false, 0, 0x80, 0x80)};
  checkHandCase(image, 2, {-0.25, -0.25, -5}, {0, 0, 1}, {true, 4.5, 2, 2, 1, 1, 1, 6 << 3 | 7});
  // The far word's offset is added modulo 2^32: here the children are 6 words before the root.
  const std::vector<uint32_t> wrapped{
      decoy, descriptor(false, 0, 0x80, 0x80), decoy,      decoy, decoy, decoy,
      decoy, descriptor(true, 1, 0x01, 0x00),  0xFFFFFFFAu};
  checkHandCase(wrapped, 7, {-0.25, -0.25, -5}, {0, 0, 1}, {true, 4.5, 2, 2, 1, 1, 1, 1 << 3 | 7});
}

TEST_CASE("Voxel walk: refuses a zero direction and a cycle of child pointers", "[voxel-walk]") {
  const std::vector<uint32_t> image{descriptor(false, 0, 0x01, 0x00)};  // its child is itself
  CHECK_THROWS_AS(walkVoxels(WordMemory(image), 0, {0, 0, -3}, {0, 0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(walkVoxels(WordMemory(image), 0, {-1, -1, -3}, {0, 0, 1}), std::runtime_error);
}

namespace {

struct VoxelWalkAgreement {
  size_t rays = 0, oracleHits = 0, goldenHits = 0;
  long farPointers = 0;  // far words the walks read
  size_t agree = 0;      // both miss, or both hit the same voxel with t within tolerance
  size_t grazing = 0;    // rays whose walk took a decision within the golden model's error
  size_t hitMiss = 0, otherVoxel = 0, tBeyond = 0;  // disagreements...
  size_t explained = 0;     // ... of grazing rays, whose golden answer a ray within its error gets
  size_t flagged = 0;       // tOverflow or belowResolution: the golden model says it is unreliable
  double maxTError = 0.0;   // over the agreeing hits
  std::string unexplained;  // the first few disagreements with clearance left
  // The float64 reference (the traversal core in double): disagreements with the walk, and those
  // of them on rays passing within 1e-9 in t of an edge of the grid (ties, decided by convention).
  size_t referenceDisagree = 0, referenceTies = 0;

  size_t disagree() const { return hitMiss + otherVoxel + tBeyond; }
};

// The golden model's t-values on axis k are within u_k of the exact ones (in t):
// - the job's float32 set-up (normalisation, mirroring, (+-1 - o) / d) rounds each t-value by a
//   few float32 ulps: 2^-21 of the largest |t| on that axis (2^3 ulps of 2^-24) covers it;
// - the RTL conversion to Q16.16 truncates and, for odd exponents, clears the least significant
//   bit, and flushes |t| < 2^-14 to 0: at most 4 steps;
// - every level of the descent halves t0 + t1 with an arithmetic shift, truncating by at most one
//   more step, and a voxel at depth D is D halvings below the root: D steps.
// A decision of the walk whose two plane crossings are more than u_j + u_k apart in t is taken
// the same way by the golden model; a ray with a decision closer than that somewhere on its walk
// grazes the grid (VoxelWalkResult::clearance <= 0). At depth 7 u is about 1.7e-4 (1/150 of a
// voxel's extent in t along a diagonal ray), but a ray decides at every cell it crosses: 2-4 % of a
// frame's rays graze somewhere, 15 % in noise, whose rays cross many empty cells. So grazing is
// only a necessary condition: a disagreement counts as explained when, in addition, the walk of a
// ray within that error reproduces the golden model's answer (reproduced below).
std::array<double, 3> goldenUncertainty(const TValueRecord& job, int depth) {
  std::array<double, 3> u{};
  for (int k = 0; k < 3; ++k) {
    const double largest = std::max(std::abs(static_cast<double>(bitsToFloat(job.t0Bits[k]))),
                                    std::abs(static_cast<double>(bitsToFloat(job.t1Bits[k]))));
    u[k] = (depth + 4) * kStep + std::ldexp(largest, -21);
  }
  return u;
}

// Whether the exact answer for some ray within the golden model's error is the golden model's
// (a miss, or the same voxel entered at a t within the error): the walk along the same direction
// from origins moved along each axis k by -1, -1/2, 0, 1/2 or 1 times u_k |d_k|, which moves
// that axis' plane crossings by up to u_k in t.
bool reproduced(const WordMemory& memory, uint32_t root, const Ray& ray,
                const std::array<double, 3>& u, bool hit, uint64_t voxel, double tHit) {
  const glm::dvec3 d = jobLineDirection(ray.direction, kDefaultDirectionEpsilon);
  const double tolerance = 2 * std::max({u[0], u[1], u[2]});
  for (int i = 0; i < 125; ++i) {
    glm::dvec3 origin = ray.origin;
    for (int k = 0, code = i; k < 3; ++k, code /= 5)
      origin[k] += (code % 5 - 2) * 0.5 * u[k] * std::abs(d[k]);
    const VoxelWalkResult walk = walkVoxels(memory, root, origin, d);
    if (walk.hit == hit &&
        (!hit || (walk.voxelKey == voxel && std::abs(walk.tHit - tHit) <= tolerance)))
      return true;
  }
  return false;
}

VoxelWalkAgreement compareWithGolden(const SvoBuild& build, const std::vector<Ray>& rays) {
  const WordMemory memory = build.image.memory();
  const uint32_t root = build.image.root;
  GoldenModel golden(memory, GoldenConfig{});
  ReferenceModel reference(memory, kDefaultDirectionEpsilon);
  const FixedFormat format = golden.config().format;
  VoxelWalkAgreement a;
  for (const Ray& ray : rays) {
    const ReferenceResult exact = reference.trace(ray, root);
    const TValueRecord job = makeTValueRecord(0, ray, root, kDefaultDirectionEpsilon);
    const TraversalResult fixed = golden.trace(job);
    const uint64_t fixedVoxel = golden.lastHitVoxel();
    VoxelWalkOptions options;
    options.tUncertainty = goldenUncertainty(job, build.stats.depth);
    const VoxelWalkResult walk =
        walkVoxels(memory, root, ray.origin,
                   jobLineDirection(ray.direction, kDefaultDirectionEpsilon), options);
    ++a.rays;
    if (exact.hit != walk.hit ||
        (walk.hit && (exact.voxel != walk.voxelKey || std::abs(exact.tHit - walk.tHit) > 1e-9))) {
      ++a.referenceDisagree;
      VoxelWalkOptions tie;
      tie.tUncertainty = {0.5e-9, 0.5e-9, 0.5e-9};
      a.referenceTies += walkVoxels(memory, root, ray.origin,
                                    jobLineDirection(ray.direction, kDefaultDirectionEpsilon), tie)
                             .clearance <= 0.0;
    }
    a.farPointers += walk.farPointers;
    a.oracleHits += walk.hit;
    a.goldenHits += fixed.hit;
    a.flagged += fixed.tOverflow || fixed.belowResolution || fixed.stackOverflow;
    const bool grazing = walk.clearance <= 0.0;
    a.grazing += grazing;
    double tError = 0.0;
    bool agrees = fixed.hit == walk.hit;
    if (!agrees) {
      ++a.hitMiss;
    } else if (walk.hit && fixedVoxel != walk.voxelKey) {
      ++a.otherVoxel;
      agrees = false;
    } else if (walk.hit) {
      tError = std::abs(format.toDouble(fixed.tHit) - walk.tHit);
      int fixedAxis = 0;
      while (fixedAxis < 2 && fixed.normal[fixedAxis] == 0) ++fixedAxis;
      const double tolerance =
          std::max(options.tUncertainty[walk.entryAxis], options.tUncertainty[fixedAxis]);
      if (tError > tolerance) {
        ++a.tBeyond;
        agrees = false;
      }
    }
    if (agrees) {
      ++a.agree;
      a.maxTError = std::max(a.maxTError, tError);
    } else if (grazing && reproduced(memory, root, ray, options.tUncertainty, fixed.hit, fixedVoxel,
                                     format.toDouble(fixed.tHit))) {
      ++a.explained;
    } else if (a.unexplained.size() < 2000) {
      std::ostringstream text;
      text << "  ray o=(" << ray.origin.x << "," << ray.origin.y << "," << ray.origin.z << ") d=("
           << ray.direction.x << "," << ray.direction.y << "," << ray.direction.z << "): golden "
           << (fixed.hit ? "hit" : "miss") << " t=" << format.toDouble(fixed.tHit) << " voxel "
           << fixedVoxel << ", walk " << (walk.hit ? "hit" : "miss") << " t=" << walk.tHit
           << " voxel " << walk.voxelKey << " (level " << walk.level << " " << walk.x << ","
           << walk.y << "," << walk.z << "), clearance " << walk.clearance << "\n";
      a.unexplained += text.str();
    }
  }
  return a;
}

}  // namespace

// Eight cameras, one in each octant around the model looking at its centre, so that rays run in
// all eight direction octants (every mirroring a of the job set-up); 32x32 pixels each.
std::vector<Ray> eightViews() {
  std::vector<Ray> rays;
  for (int octant = 0; octant < 8; ++octant) {
    Camera camera;
    camera.position =
        glm::dvec3(octant & 1 ? 1.9 : -1.9, octant & 2 ? 1.3 : -1.3, octant & 4 ? 2.6 : -2.6);
    camera.width = 32;
    camera.height = 32;
    const std::vector<Ray> view = frameRays(camera);
    rays.insert(rays.end(), view.begin(), view.end());
  }
  return rays;
}

// The SVO kind's oracle check (tests/test_kind_oracles.cpp): the walk agrees with the golden
// model on every procedural scene but grazing rays.
void KindFixture<SvoKind>::checkOracle() {
  const std::vector<Ray> rays = eightViews();
  long farPointers = 0;
  for (const std::string& name : proceduralSceneNames()) {
    const SvoBuild build = buildSvo(*makeProceduralScene(name, kDepth));
    const VoxelWalkAgreement a = compareWithGolden(build, rays);
    farPointers += a.farPointers;
    INFO(name << " depth " << kDepth << " (" << build.stats.describe() << "), " << a.rays
              << " rays: " << a.oracleHits << " walk hits, " << a.goldenHits
              << " golden hits; agree " << a.agree << "; disagree " << a.disagree() << " (hit/miss "
              << a.hitMiss << ", other voxel " << a.otherVoxel << ", t " << a.tBeyond
              << "), explained " << a.explained << "; grazing rays " << a.grazing
              << "; far words read " << a.farPointers << "; max |t error| of agreeing hits "
              << a.maxTError << "; float64 reference disagrees on " << a.referenceDisagree << ", "
              << a.referenceTies << " of them ties\n"
              << a.unexplained);
    CHECK(a.flagged == 0);
    CHECK(a.oracleHits > a.rays / 10);    // the scene fills part of the frame
    CHECK(a.disagree() == a.explained);   // every disagreement is a grazing ray, reproduced
    CHECK(a.disagree() * 200 <= a.rays);  // and they are rare: at most 0.5 %
    CHECK(a.referenceDisagree == a.referenceTies);  // float64 and the walk differ on ties only
  }
  CHECK(farPointers > 0);  // the rays went through far pointers of the scenes that have them
}

}  // namespace rtu
