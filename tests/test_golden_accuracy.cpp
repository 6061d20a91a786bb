// The fixed-point golden model against the float64 reference on every procedural scene.
#include <catch2/catch.hpp>

#include "inputs/camera.h"
#include "kinds/svo/accuracy.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"

using namespace rtu;

namespace {

// White noise is the one scene below 99.9 %: with the RTL's conversion, 68 of 65536 rays graze an
// isolated voxel within Q16.16's resolution and hit a different one (docs/accuracy.md). That is
// the thesis arithmetic, which the golden model must reproduce bit for bit.
double requiredAgreement(const std::string& scene, FloatConversion conversion) {
  return scene == "noise" && conversion == FloatConversion::Rtl ? 0.9985 : 0.999;
}

}  // namespace

TEST_CASE("Golden agrees with float64 on at least 99.9 % of a 256x256 frame",
          "[golden][accuracy]") {
  Camera camera;
  camera.width = 256;
  camera.height = 256;
  const std::vector<Ray> rays = frameRays(camera);
  for (const std::string& name : proceduralSceneNames()) {
    const SvoBuild build = buildSvo(*makeProceduralScene(name, 8));
    for (FloatConversion conversion : {FloatConversion::Rtl, FloatConversion::Exact}) {
      GoldenConfig config;
      config.conversion = conversion;
      const AccuracyReport report = measureAccuracy(build.image.memory(), build.image.root, rays,
                                                    config, kDefaultDirectionEpsilon, 1e-3);
      INFO(name << " (" << toString(conversion) << " conversion)\n" << report.describe());
      CHECK(report.referenceHits > rays.size() / 10);  // the scene fills part of the frame
      CHECK(report.agreement() >= requiredAgreement(name, conversion));
    }
  }
}

TEST_CASE("Rays that overflow the stack are counted apart\\, not as disagreements",
          "[golden][accuracy]") {
  Camera camera;
  camera.width = 64;
  camera.height = 64;
  const std::vector<Ray> rays = frameRays(camera);
  const SvoBuild build = buildSvo(*makeProceduralScene("sphere", 6));
  GoldenConfig config;
  config.stackFrames = 2;  // the tree needs 5: allowed, its deeper rays are flagged
  const AccuracyReport report = measureAccuracy(build.image.memory(), build.image.root, rays,
                                                config, kDefaultDirectionEpsilon, 1e-3);
  INFO(report.describe());
  CHECK(report.stackOverflows > rays.size() / 10);
  CHECK(report.compared() == rays.size() - report.stackOverflows);
  CHECK(report.agreement() >= 0.999);  // they were the "50 % agreement" of issue 33
}

TEST_CASE("More fraction bits bring the golden model closer to float64", "[golden][accuracy]") {
  Camera camera;
  camera.width = 128;
  camera.height = 128;
  const std::vector<Ray> rays = frameRays(camera);
  const SvoBuild build = buildSvo(*makeProceduralScene("noise", 8));
  double previousError = 1e9;
  for (int fraction : {12, 16, 20, 24}) {
    GoldenConfig config;
    config.format = FixedFormat{32, fraction};
    const AccuracyReport report = measureAccuracy(build.image.memory(), build.image.root, rays,
                                                  config, kDefaultDirectionEpsilon, 1e-3);
    INFO("Q" << 32 - fraction << "." << fraction << "\n" << report.describe());
    REQUIRE(report.meanTError < previousError);
    previousError = report.meanTError;
  }
}
