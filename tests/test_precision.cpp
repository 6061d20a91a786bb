// rtusim precision's measure (src/kinds/svo/precision.h): formats against float64.

#include <catch2/catch.hpp>

#include "inputs/camera.h"
#include "kinds/svo/precision.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"

namespace rtu {
namespace {

struct Study {
  SvoBuild build;
  PrecisionStudy study;
};

Study sphereStudy(int depth, int size) {
  Study s{buildSvo(*makeProceduralScene("sphere", depth)), {}};
  Camera camera;
  camera.width = size;
  camera.height = size;
  s.study.rays = frameRays(camera);
  s.study.root = s.build.image.root;
  return s;
}

size_t count(const FormatPrecision& p, PrecisionVerdict verdict) {
  return static_cast<size_t>(std::count(p.verdicts.begin(), p.verdicts.end(), verdict));
}

}  // namespace

TEST_CASE("Formats are written QI.F, a bare A.B only where one reading is a format",
          "[precision]") {
  CHECK(parseFixedFormat("Q16.16").totalBits == 32);
  CHECK(parseFixedFormat("Q16.16").fractionBits == 16);
  CHECK(parseFixedFormat("Q12.20").totalBits == 32);
  CHECK(parseFixedFormat("Q12.20").fractionBits == 20);
  // 16 bits cannot hold 16 fraction bits and a sign: only Q16.16 reads "16.16".
  CHECK(parseFixedFormat("16.16").totalBits == 32);
  CHECK(parseFixedFormat("16.16").fractionBits == 16);
  // Q48.32 would be 80 bits: only 48 bits with 32 of them fraction (Q16.32) reads "48.32".
  CHECK(parseFixedFormat("48.32").totalBits == 48);
  CHECK(parseFixedFormat("48.32").fractionBits == 32);
  // Both Q8.12 (20 bits) and Q20.12 (32 bits) read "20.12".
  CHECK_THROWS_WITH(parseFixedFormat("20.12"),
                    Catch::Contains("format '20.12' is ambiguous: write Q8.12 (20 bits) or "
                                    "Q20.12 (32 bits)"));
  CHECK_THROWS_WITH(parseFixedFormat("32"),
                    Catch::Contains("format '32'") && Catch::Contains("Q16.16"));
  CHECK_THROWS_WITH(parseFixedFormat("32.x"), Catch::Contains("format '32.x'"));
  CHECK_THROWS_WITH(parseFixedFormat("64.16"), Catch::Contains("format '64.16'"));
  CHECK_THROWS_WITH(parseFixedFormat("Q40.16"), Catch::Contains("format 'Q40.16'"));
  CHECK_THROWS_WITH(parseFixedFormat("1.2.3"), Catch::Contains("format '1.2.3'"));
  CHECK_THROWS_WITH(parseFixedFormat("2147483647.2147483647"), Catch::Contains("format '"));
}

TEST_CASE("Every ray gets one verdict, and the counts agree with them", "[precision]") {
  const Study s = sphereStudy(6, 48);
  const auto results =
      measurePrecision(s.build.image.memory(), s.study, {FixedFormat{16, 8}, FixedFormat{32, 16}});
  for (const FormatPrecision& p : results) {
    REQUIRE(p.verdicts.size() == s.study.rays.size());
    CHECK(count(p, PrecisionVerdict::FalseHit) == p.falseHits);
    CHECK(count(p, PrecisionVerdict::MissedHit) == p.missedHits);
    CHECK(count(p, PrecisionVerdict::DifferentVoxel) == p.differentVoxels);
    // float64 hits are the rays where it hits: agreeing, missed, or on another voxel.
    CHECK(count(p, PrecisionVerdict::Agree) + p.missedHits + p.differentVoxels == p.referenceHits);
    CHECK(p.referenceHits > 0);
  }
}

TEST_CASE("Wide formats agree with float64, 8 fraction bits cannot resolve depth-8 leaves",
          "[precision]") {
  // A depth-8 leaf spans 2^-7 of the cube: with 8 fraction bits a child's t-interval is a few
  // steps wide, and truncated midpoints put hits into neighbouring leaves.
  const Study s = sphereStudy(8, 64);
  const auto results =
      measurePrecision(s.build.image.memory(), s.study,
                       {FixedFormat{16, 8}, FixedFormat{32, 16}, FixedFormat{48, 24}});
  const FormatPrecision& narrow = results[0];
  const FormatPrecision& thesis = results[1];
  const FormatPrecision& wide = results[2];
  CHECK(narrow.differentVoxelRate() > 0.05);
  CHECK(thesis.differentVoxelRate() < 0.01);
  CHECK(wide.differentVoxels + wide.falseHits + wide.missedHits == 0);
  // Truncation errs by a few steps of the format, not more, where the voxels agree.
  CHECK(thesis.tErrorMeanSteps < 4.0);
  CHECK(thesis.tErrorMeanSteps > 0.5);
}

TEST_CASE("An invalid format is refused before tracing", "[precision]") {
  const Study s = sphereStudy(4, 4);
  CHECK_THROWS_AS(measurePrecision(s.build.image.memory(), s.study,
                                   {FixedFormat{32, 16}, FixedFormat{64, 16}}),
                  std::invalid_argument);
}

}  // namespace rtu

namespace rtu {

TEST_CASE("t-values beyond the range are flagged where a sum wraps, and only there",
          "[precision]") {
  const Study s = sphereStudy(8, 96);
  // The default camera's t-values reach about 5 inside the cube, but a slanted axis leaves its
  // slab much later, and midpoints add two t-values: Q4.12 (range +-8) wraps for most rays, Q7.12
  // (+-64) for none (docs/precision.md).
  const auto results =
      measurePrecision(s.build.image.memory(), s.study,
                       {FixedFormat{16, 12}, FixedFormat{19, 12}, FixedFormat{32, 16}});
  const FormatPrecision& tooFewIntegerBits = results[0];
  CHECK(tooFewIntegerBits.wrongHitMissRate() > 0.2);
  CHECK(tooFewIntegerBits.tOverflowRays >
        tooFewIntegerBits.falseHits + tooFewIntegerBits.missedHits);
  // What the flag leaves is ordinary 12-fraction-bit imprecision, as Q7.12 has.
  CHECK(tooFewIntegerBits.wrongUnflagged <=
        results[1].differentVoxels + results[1].falseHits + results[1].missedHits + 5);
  CHECK(results[1].tOverflowRays == 0);
  CHECK(results[2].tOverflowRays == 0);
}

TEST_CASE("A camera far outside the volume is flagged, not silently wrong", "[precision]") {
  // 20,000 units away in Q16.16 (range +-32768): t0 + t1 of the root exceeds the range.
  Study s = sphereStudy(6, 1);  // its one default ray is replaced below
  Camera far;
  far.width = 16;
  far.height = 16;
  far.position = glm::dvec3(0.0, 0.0, -20000.0);
  far.verticalFovDegrees = 0.004;
  s.study.rays = frameRays(far);
  const FormatPrecision thesis =
      measurePrecision(s.build.image.memory(), s.study, {FixedFormat{32, 16}})[0];
  CHECK(thesis.referenceHits > 0);
  CHECK(thesis.tOverflowRays >= thesis.referenceHits);
  CHECK(thesis.wrongUnflagged == 0);
}

}  // namespace rtu
