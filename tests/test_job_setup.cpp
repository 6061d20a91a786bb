// The job manager's behaviour (src/kinds/svo/job_setup.h): latencies counted by hand from its
// configuration, the model header read once per model.

#include <catch2/catch.hpp>

#include "inputs/camera.h"
#include "kinds/svo/golden_config.h"
#include "kinds/svo/job_setup.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_image.h"

namespace rtu {

TEST_CASE("Job set-up: latencies of t-value and ray records, one header fetch per model",
          "[job_manager]") {
  SvoImage image = buildSvo(*makeProceduralScene("sphere", 4)).image;
  const uint32_t first = appendModelHeader(image, ModelPlacement{});
  ModelPlacement moved;
  moved.translation = {0.5, 0, 0};
  const uint32_t second = appendModelHeader(image, moved);
  Camera camera;
  camera.width = 2;
  camera.height = 1;
  const std::vector<RayRecord> firstRays = makeFrameRayRecords(camera, first);
  const std::vector<RayRecord> secondRays = makeFrameRayRecords(camera, second);

  const JobManagerTiming timing{6, 4, 16};
  JobSetup setup(image.memory(), timing, GoldenConfig{}.epsilon);

  const TValueRecord tValues = makeFrameJobs(camera, image.root).front();
  const JobSetup::SetUp plain = setup.setUp(tValues);
  CHECK(plain.latency == 6);
  CHECK(plain.headerFetch == 0);
  CHECK(plain.job.t0Bits == tValues.t0Bits);

  const JobSetup::SetUp firstRay = setup.setUp(firstRays[0]);
  CHECK(firstRay.latency == 6 + 4 + 16);
  CHECK(firstRay.headerFetch == 16);
  const JobSetup::SetUp again = setup.setUp(firstRays[1]);
  CHECK(again.latency == 6 + 4);
  CHECK(again.headerFetch == 0);
  const JobSetup::SetUp otherModel = setup.setUp(secondRays[0]);
  CHECK(otherModel.headerFetch == 16);
  // the same pixel's ray against a model moved along x enters it elsewhere
  CHECK(otherModel.job.t0Bits != firstRay.job.t0Bits);
}

}  // namespace rtu
