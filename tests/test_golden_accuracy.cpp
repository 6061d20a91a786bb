// The fixed-point golden model against the float64 reference on every procedural scene.
#include <catch2/catch.hpp>

#include "accuracy.h"
#include "camera.h"
#include "procedural_scenes.h"
#include "svo_builder.h"

using namespace rtu;

TEST_CASE("Golden agrees with float64 on at least 99.9 % of a 256x256 frame", "[golden][accuracy]") {
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
      REQUIRE(report.referenceHits > rays.size() / 10);  // the scene fills part of the frame
      REQUIRE(report.agreement() >= 0.999);
    }
  }
}
