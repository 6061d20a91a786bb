// A windowed timeline (src/trace/timeline_writer.h) costs about its window: before it the
// timeline hears only the handshakes its counters count, then the values the rest holds, and
// nothing once its window and the rays that started in it have ended. Its file equals the one a
// timeline with the same window writes when it hears the whole run, and a run that only counts
// it stops soon after the window.

#include <catch2/catch.hpp>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "inputs/camera.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_kind.h"
#include "run/rtu_simulation.h"
#include "temp_path.h"
#include "trace/timeline_writer.h"

namespace rtu {
namespace {

struct WindowFrame {
  SvoBuild build;
  std::vector<HostRecord> records;
  WordMemory memory() const { return build.image.memory(); }
};

WindowFrame makeFrame(int width, int height) {
  WindowFrame f{buildSvo(*makeProceduralScene("sphere", 6)), {}};
  Camera camera;
  camera.width = width;
  camera.height = height;
  const std::vector<TValueRecord> jobs = makeFrameJobs(camera, f.build.image.root);
  f.records.assign(jobs.begin(), jobs.end());
  return f;
}

RtuConfig cachedFourCores() {
  RtuConfig config;
  config.cores = 4;
  config.memory = MemoryConfig{};
  return config;
}

// Hears the whole run on a timeline's behalf, as every timeline did before it had a window of
// its own: it passes on the records but not the timeline's window.
class WholeRun : public TraceListener {
 public:
  explicit WholeRun(TimelineWriter& timeline) : timeline_(timeline) {}
  void declared(size_t signal, const std::string& scope, const TraceVariable& variable) override {
    timeline_.declared(signal, scope, variable);
  }
  void changed(uint64_t cycle, const std::vector<TraceChange>& changes) override {
    timeline_.changed(cycle, changes);
  }
  void finished() override { timeline_.finished(); }

 private:
  TimelineWriter& timeline_;
};

std::string contents(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

constexpr uint64_t kPeriodPs = 10000;  // 100 MHz, the default clock

}  // namespace

TEST_CASE("A windowed timeline equals the one that heard the whole run", "[timeline]") {
  const WindowFrame f = makeFrame(32, 24);
  const RtuConfig base = cachedFourCores();
  const uint64_t total = simulateRtu(f.memory(), f.records, base).totalCycles;
  REQUIRE(total > 3000);
  const std::vector<std::pair<uint64_t, uint64_t>> windows{
      {total / 3, total / 3 + 400}, {0, 150}, {total - 200, total + 50}};
  for (const auto& [from, to] : windows) {
    INFO("window [" << from << ", " << to << ")");
    TempPath windowed("windowed.json"), whole("whole.json");
    RtuConfig config = base;
    config.timeline = TimelineOptions{windowed.str(), from, to};
    simulateRtu(f.memory(), f.records, config);
    TimelineWriter timeline(TimelineOptions{whole.str(), from, to}, kPeriodPs,
                            SvoKind::vocabulary());
    WholeRun listener(timeline);
    simulateRtu(f.memory(), f.records, base, {}, {&listener});
    const std::string text = contents(windowed.str());
    CHECK(text.find("\"ray ") != std::string::npos);
    CHECK(text.find("\"BLOCKED\"") != std::string::npos);
    CHECK(text == contents(whole.str()));
  }
}

// The run stops once the window and its rays have ended: bounded in simulated cycles, not in
// wall time. A flush interval (4096 cycles) and the window's longest ray may follow the window.
TEST_CASE("A run that only counts a windowed timeline stops soon after the window", "[timeline]") {
  const WindowFrame f = makeFrame(96, 72);
  RtuConfig config = cachedFourCores();
  const RtuRun full = simulateRtu(f.memory(), f.records, config);
  const uint64_t from = 1000, to = 1400;
  REQUIRE(full.totalCycles > 4 * (to + 4096));
  TempPath written("written.json");
  config.timeline = TimelineOptions{written.str(), from, to};
  simulateRtu(f.memory(), f.records, config);
  config.timeline.countOnly = true;
  const RtuRun counted = simulateRtu(f.memory(), f.records, config);
  CHECK(counted.timelineBytes == contents(written.str()).size());
  CHECK(counted.simulatedCycles >= to);
  CHECK(counted.simulatedCycles < 2 * (to + 4096));
  CHECK(counted.simulatedCycles < full.simulatedCycles / 4);
}

}  // namespace rtu
