// The host's side of a run as streams (kinds/host_stream.h): records made one at a time when the
// run asks for them, results taken as they leave it. A streamed run answers as a run over vectors
// does, and the rays its host holds at once (made, not yet taken) stay bounded by the RTU's
// buffers whatever the frame's size (issue 33, docs/robustness.md "Memory").

#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "explore/frame_scene.h"
#include "kinds/host_stream.h"
#include "run/analytic_run.h"
#include "run/model_run.h"
#include "run/rtu_simulation.h"

namespace rtu {
namespace {

RunConfig frameOf(const std::string& core, int width, int height) {
  RunConfig settings;
  settings.rtu.core = core;
  settings.scene.procedural = "sphere";
  settings.scene.depth = 6;
  settings.camera.width = width;
  settings.camera.height = height;
  return settings;
}

// The frame's records made one at a time from a vector, counted as held from when they are made.
RecordSource countedSource(const std::vector<HostRecord>& records, RaysHeld& held) {
  return RecordSource(
      records.size(),
      [&records, &held](uint64_t index) {
        held.madeOne();
        return records[index];
      },
      records.front());
}

// Results taken by job index, counted as no longer held.
ResultTaker collectingTaker(std::vector<CoreKindResult>& results, RaysHeld& held) {
  return [&results, &held](uint64_t job, const CoreKindResult& result) {
    held.tookOne();
    results.at(job) = result;
  };
}

nlohmann::ordered_json withoutHostTime(RtuStatistics statistics) {
  statistics.hostSeconds = 0;
  return statistics.toJson();
}

// The most rays a streamed run of a frame on `model` (ca or lt) holds at once; checks its results
// and statistics against the same run over vectors.
uint64_t mostHeldByStreamedRun(ModelKind model, const std::string& core, int width, int height) {
  const RunConfig settings = frameOf(core, width, height);
  const FrameScene scene = loadFrameScene(settings);
  const std::vector<HostRecord> records = frameRecords(scene, settings);
  const RtuRun kept = runModel(model, scene.memory(), records, settings.rtu);

  RaysHeld held;
  std::vector<CoreKindResult> taken(records.size());
  const RtuRun streamed = runFrame(model, scene.memory(), countedSource(records, held),
                                   settings.rtu, collectingTaker(taken, held));
  CHECK(streamed.results.empty());
  CHECK(held.made == records.size());
  CHECK(held.taken == records.size());
  CHECK(taken == resultsInJobOrder(kept));
  CHECK(streamed.totalCycles == kept.totalCycles);
  CHECK(withoutHostTime(streamed.statistics) == withoutHostTime(kept.statistics));
  return held.most;
}

}  // namespace

TEST_CASE("Streamed run: the rays held at once are bounded by the RTU\\, not the frame",
          "[host_stream][lt]") {
  const std::string core = GENERATE(as<std::string>{}, "svo", "bvh");
  const ModelKind model = GENERATE(ModelKind::CycleAccurate, ModelKind::LooselyTimed);
  CAPTURE(core, toString(model));
  const uint64_t small = mostHeldByStreamedRun(model, core, 48, 32);    // 1536 rays
  const uint64_t large = mostHeldByStreamedRun(model, core, 192, 128);  // 24576 rays
  // A run that kept its results to the end would hold the whole frame. The RTU holds a few rays
  // per core (job manager pipeline, scheduler queue, cores, result buffers; the loosely-timed
  // model a job from its set-up until its result drains): the same few at 16 times the rays.
  CHECK(small > 0);
  CHECK(large <= 128);
  CHECK(large <= small + small / 2);
}

TEST_CASE("Streamed golden trace: one ray held at a time\\, the results of the vector's",
          "[host_stream]") {
  const RunConfig settings = frameOf("svo", 48, 32);
  const FrameScene scene = loadFrameScene(settings);
  const std::vector<HostRecord> records = frameRecords(scene, settings);
  RaysHeld held;
  std::vector<CoreKindResult> taken(records.size());
  traceGolden(scene.memory(), countedSource(records, held), settings.rtu,
              collectingTaker(taken, held));
  CHECK(held.most == 1);
  CHECK(taken == traceGolden(scene.memory(), records, settings.rtu));
}

TEST_CASE("Record source: a vector's records or made ones\\, checked by their alternative",
          "[host_stream]") {
  const std::vector<HostRecord> records{TValueRecord{}, TValueRecord{}};
  const RecordSource held(records);
  CHECK(held.vector() == &records);
  CHECK(held.size() == 2);
  RaysHeld counted;
  const RecordSource made = countedSource(records, counted);
  CHECK(made.vector() == nullptr);
  CHECK(made.all().size() == 2);
  CHECK(counted.made == 2);
  CHECK_NOTHROW(checkCoreTakes("svo", made));
  CHECK_THROWS_AS(checkCoreTakes("bvh", made), std::invalid_argument);
}

}  // namespace rtu
