// The timed ray pipe's cycle trace (sim/raypipe/pipe_trace.h): one ray on one triangle shows each
// unit's transfer in the cycle counted by hand in docs/raypipe.md (tests/test_raypipe_cycles.cpp's
// table), with its ray id; on a frame of PRG rays with stalls, every unit's transfers in the trace
// (valid & ~stall) are the per-cycle reference's, its stalled cycles (valid & stall) add up to the
// reference's stall counts (a cycle once where the shortstack counts each waiting input), and every
// FIFO's count reaches the reference's peak; the VCD declares the pipe's scopes and the save file
// groups them in the pipe's order.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "raypipe_scenes.h"
#include "reference/raypipe_cycles.h"
#include "sim/raypipe/raypipe_timed.h"
#include "trace/gtkw_save_file.h"
#include "trace/trace_listener.h"

namespace rtu {
namespace {

// Every signal's value in every cycle from 0 to the last change, rebuilt from the changes a trace
// listener hears.
class SignalLevels : public TraceListener {
 public:
  void declared(size_t signal, const std::string& scope, const TraceVariable& variable) override {
    names_.resize(signal + 1);
    names_[signal] = scope + "." + variable.name;
  }
  void changed(uint64_t cycle, const std::vector<TraceChange>& changes) override {
    for (const TraceChange& c : changes) changes_[names_[c.signal]].emplace_back(cycle, c.value);
    last_ = std::max(last_, cycle);
  }
  bool has(const std::string& name) const { return changes_.count(name) > 0; }
  // The value of `name` in each cycle 0 .. last.
  std::vector<uint64_t> levels(const std::string& name) const {
    std::vector<uint64_t> values(last_ + 2, 0);
    const auto& list = changes_.at(name);
    for (size_t i = 0; i < list.size(); ++i) {
      const uint64_t end = i + 1 < list.size() ? list[i + 1].first : values.size();
      std::fill(values.begin() + static_cast<long>(list[i].first),
                values.begin() + static_cast<long>(end), list[i].second);
    }
    return values;
  }

 private:
  std::vector<std::string> names_;
  std::map<std::string, std::vector<std::pair<uint64_t, uint64_t>>> changes_;
  uint64_t last_ = 0;
};

using Transfer = std::tuple<int64_t, std::string, uint64_t>;  // cycle, unit, ray id (PRG: pixel)

// The transfers the trace shows: cycles with valid and no stall, with the unit's id then.
std::vector<Transfer> tracedTransfers(const SignalLevels& levels, int64_t* stalls = nullptr,
                                      std::map<std::string, int64_t>* stallsByUnit = nullptr) {
  std::vector<Transfer> seen;
  for (size_t u = 0; u < static_cast<size_t>(RaypipeUnit::kCount); ++u) {
    const std::string unit = raypipeUnitName(static_cast<RaypipeUnit>(u));
    const std::string scope = "raypipe." + unit;
    const auto valid = levels.levels(scope + ".valid"), stall = levels.levels(scope + ".stall");
    const auto id = levels.levels(scope + (unit == "prg" ? ".pixel" : ".ray"));
    for (size_t c = 0; c < valid.size(); ++c) {
      if (valid[c] && !stall[c]) seen.emplace_back(static_cast<int64_t>(c), unit, id[c]);
      if (valid[c] && stall[c] && stallsByUnit) ++(*stallsByUnit)[unit];
      if (stall[c] && !valid[c] && stalls) ++*stalls;  // a stall without an offer: none expected
    }
  }
  std::sort(seen.begin(), seen.end());
  return seen;
}

RaypipeCycleRun tracedRun(const KdImage& image, const std::vector<RaypipeCycleRay>& rays,
                          const RaypipeConfig& config, SignalLevels& levels) {
  CycleTrace trace(TraceOptions{}, {&levels});  // no file: the listener hears every signal
  return runRaypipeTimed(config, image, rays, {}, &trace);
}

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("raypipe trace: one ray's transfers in the hand-counted cycles", "[raypipe_trace]") {
  SignalLevels levels;
  RaypipeConfig config;
  const RaypipeCycleRun run = tracedRun(oneTriangle(), {{downZ(0.5f, 0.5f), 7}}, config, levels);
  REQUIRE(run.results[0].exitCycle == 143);
  const uint64_t id = run.results[0].rayId;
  const std::vector<Transfer> expected = {{0, "prg", 0},
                                          {44, "sint", id},
                                          {63, "tarb", id},
                                          {65, "tcache", id},
                                          {68, "trav", id},
                                          {70, "larb", id},
                                          {72, "lcache", id},
                                          {75, "icache", id},
                                          {81, "int", id},
                                          {128, "list", id},
                                          {139, "shader_arb", id},
                                          {140, "shader_return", id},
                                          {144, "pixel_writer", id}};
  int64_t stallsWithoutOffer = 0;
  CHECK(tracedTransfers(levels, &stallsWithoutOffer) == expected);
  CHECK(stallsWithoutOffer == 0);
  // The FIFOs on its way: the PRG's holds the pixel from 42 (written at 41, counted from the next
  // cycle) until SINT reads it at 44; the pixel buffer holds it from 144 to the writer's read.
  const auto prg = levels.levels("raypipe.fifos.prg.count");
  CHECK(prg[41] == 0);
  CHECK(prg[42] == 1);
  CHECK(prg[44] == 1);
  CHECK(prg[45] == 0);
  const auto pixels = levels.levels("raypipe.fifos.pixel_buffer.count");
  CHECK(pixels[143] == 0);
  CHECK(pixels[144] == 1);
  CHECK(pixels[145] == 0);
  // 512 free ray ids, one fewer while the ray holds its id (SINT takes it at 44; the shader frees
  // it as it returns, at 140).
  const auto ids = levels.levels("raypipe.fifos.shader_ray_ids.count");
  CHECK(ids[44] == 512);
  CHECK(ids[45] == 511);
  CHECK(ids[141] == 512);
}

TEST_CASE("raypipe trace: every transfer\\, stall and FIFO peak of the reference",
          "[raypipe_trace]") {
  const KdImage image = frameScene();
  const std::vector<RaypipeCycleRay> rays = prgRays(1);
  RaypipeConfig config;
  config.fifo.pixelBuffer = 2;  // the VGA window's waits reach back into the shader
  RaypipeCycleOptions options;
  options.recordTransfers = true;
  options.writer.vgaReadWindow = true;
  const RaypipeCycleRun ref = runRaypipeCycles(config, image, rays, options);
  SignalLevels levels;
  CycleTrace trace(TraceOptions{}, {&levels});
  options.recordTransfers = false;
  runRaypipeTimed(config, image, rays, options, &trace);

  std::vector<Transfer> expected;
  for (const RaypipeTransfer& t : ref.transfers)
    expected.emplace_back(t.cycle, t.unit,
                          t.rayId == RaypipeTransfer::kNoRayId ? t.index : t.rayId);
  std::sort(expected.begin(), expected.end());
  std::map<std::string, int64_t> stalls;
  int64_t stallsWithoutOffer = 0;
  CHECK(tracedTransfers(levels, &stallsWithoutOffer, &stalls) == expected);
  CHECK(stallsWithoutOffer == 0);
  int64_t stalled = 0;
  for (const RaypipeUnitActivity& unit : ref.units) {
    INFO(unit.unit);
    // The shortstack's reads count each of their three inputs that waits; the trace shows a
    // cycle with any waiting once.
    if (unit.unit == "ss_stack" || unit.unit == "ss_restart") {
      CHECK(stalls[unit.unit] <= unit.stall);
      CHECK((stalls[unit.unit] > 0) == (unit.stall > 0));
    } else {
      CHECK(stalls[unit.unit] == unit.stall);
    }
    stalled += unit.stall;
  }
  CHECK(stalled > 1000);  // the case has stalls to show
  for (const RaypipeFifoPeak& fifo : ref.fifos) {
    INFO(fifo.fifo);
    const auto count = levels.levels("raypipe.fifos." + fifo.fifo + ".count");
    const int peak = static_cast<int>(*std::max_element(count.begin(), count.end()));
    CHECK(peak == fifo.peak);
  }
}

TEST_CASE("raypipe trace: a VCD with the pipe's scopes and a save file in the pipe's order",
          "[raypipe_trace]") {
  namespace fs = std::filesystem;
  const std::string path =
      (fs::temp_directory_path() / ("rtusim_pipe_" + std::to_string(getpid()) + ".vcd")).string();
  TraceOptions options;
  options.path = path;
  options.periodPs = 20000;  // 50 MHz
  options.time = TraceTime::Picoseconds;
  {
    CycleTrace trace(options);
    RaypipeConfig config;
    runRaypipeTimed(config, oneTriangle(), {{downZ(0.5f, 0.5f), 7}}, {}, &trace);
  }
  const std::string vcd = fileText(path), save = fileText(saveFilePath(path));
  fs::remove(path);
  fs::remove(saveFilePath(path));
  CHECK(vcd.find("$scope module raypipe $end") != std::string::npos);
  CHECK(vcd.find("$scope module trav $end") != std::string::npos);
  CHECK(vcd.find("$var wire 9 ") != std::string::npos);  // 512 ray ids
  CHECK(vcd.find("#2860000\n") != std::string::npos);    // the exit at 143, the pixel buffer at 144
  // Groups: the units in the pipe's order, then the FIFOs; the marker at the exit (143).
  const size_t prg = save.find("\n-prg\n"), sint = save.find("\n-sint\n"),
               writer = save.find("\n-pixel_writer\n"), fifos = save.find("\n-fifos\n");
  REQUIRE(prg != std::string::npos);
  CHECK(prg < sint);
  CHECK(sint < writer);
  CHECK(writer < fifos);
  CHECK(save.find("+{tarb count} raypipe.fifos.tarb.count[9:0]") != std::string::npos);
  CHECK(save.find(" 2860000 -1") != std::string::npos);
}

}  // namespace rtu
