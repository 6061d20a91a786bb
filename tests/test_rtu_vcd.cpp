// The VCD trace of the SystemC RTU model (RtuConfig::trace, src/trace/cycle_trace.h): the file is
// parsed back with a small reader and its signals are checked against the run's own results
// and against the module contracts of docs/cycle-semantics.md and thesis appendix C:
//   - a ready-valid transfer happens in a cycle whose final valid and ready levels are both 1;
//   - core: in_ready = (state == IDLE), out_valid = (state == OUT); a job taken in d is in INIT
//     in d + 1; a result taken in k leaves the core IDLE in k + 1; INIT .. the last cycle
//     before OUT is the result's cost;
//   - scheduler: its job manager handshake and the core handshake are the same cycle; cfa gives
//     the job of cycle t to core t mod N, rr to the cores in turn, fa to the lowest ready core;
//   - result manager: the host takes core i's result in a cycle t with t mod N = i.
// State codes: 0 IDLE, 1 INIT, 2 EVAL, 3 NEXT, 4 PUSH, 5 POP, 6 OUT, 7 BLOCKED.

#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "inputs/camera.h"
#include "kinds/core_result.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "run/rtu_simulation.h"

namespace rtu {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// A minimal VCD reader: declarations ($scope/$var/$upscope), time stamps (#t) and value changes
// of scalars (0!, 1!, x!) and vectors (b0101 !, bx !).

class Vcd {
 public:
  // Picoseconds of a timescale rtusim writes ("1ps", "10ns", ...): times are read in ps.
  static uint64_t unitPs(const std::string& timescale) {
    const size_t digits = timescale.find_first_not_of("0123456789");
    const std::string unit = timescale.substr(digits);
    const uint64_t factor = std::stoull(timescale.substr(0, digits));
    const uint64_t scale = unit == "ps" ? 1 : unit == "ns" ? 1000 : unit == "us" ? 1000000 : 0;
    if (scale == 0) throw std::runtime_error("unexpected timescale " + timescale);
    return factor * scale;
  }

  static Vcd read(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot open " + path);
    Vcd vcd;
    std::vector<std::string> scopes;
    std::string line;
    bool definitions = true;
    uint64_t time = 0;
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      if (definitions) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "$timescale") {
          words >> vcd.timescale;
        } else if (keyword == "$scope") {
          std::string kind, name;
          words >> kind >> name;
          scopes.push_back(name);
        } else if (keyword == "$upscope") {
          if (scopes.empty()) throw std::runtime_error("unbalanced $upscope");
          scopes.pop_back();
        } else if (keyword == "$var") {
          std::string type, code, name;
          int width = 0;
          words >> type >> width >> code >> name;
          std::string full;
          for (const std::string& scope : scopes) full += scope + ".";
          full += name;
          if (vcd.codes.count(full)) throw std::runtime_error("signal declared twice: " + full);
          vcd.codes[full] = code;
          vcd.widths[full] = width;
        } else if (keyword == "$enddefinitions") {
          if (!scopes.empty()) throw std::runtime_error("scope left open");
          definitions = false;
        }
        continue;
      }
      switch (line[0]) {
        case '#':
          time = std::stoull(line.substr(1)) * unitPs(vcd.timescale);
          // (The writer repeats the first stamp after $dumpvars when values change in the
          // first cycle, so equal stamps are accepted; going back in time is not.)
          if (!vcd.times.empty() && time < vcd.times.back())
            throw std::runtime_error("time stamps going back at " + line);
          vcd.times.push_back(time);
          break;
        case '$': break;  // $dumpvars, $end
        case '0':
        case '1':
        case 'x':
        case 'z':
          vcd.change(time, line.substr(1),
                     line[0] == '0' || line[0] == '1' ? std::optional<uint64_t>(line[0] - '0')
                                                      : std::nullopt);
          break;
        case 'b': {
          const size_t space = line.find(' ');
          const std::string bits = line.substr(1, space - 1);
          std::optional<uint64_t> value;
          if (bits.find_first_not_of("01") == std::string::npos)
            value = std::stoull(bits, nullptr, 2);
          vcd.change(time, line.substr(space + 1), value);
          break;
        }
        default: throw std::runtime_error("unexpected VCD line: " + line);
      }
    }
    return vcd;
  }

  std::string timescale;
  std::map<std::string, std::string> codes;  // full name -> identifier code
  std::map<std::string, int> widths;
  std::vector<uint64_t> times;  // every #t, in file order

  bool has(const std::string& name) const { return codes.count(name) > 0; }
  std::vector<std::string> names() const {
    std::vector<std::string> all;
    for (const auto& [name, code] : codes) all.push_back(name);
    return all;
  }

  // The signal's level at the end of each cycle 0 .. cycles - 1 (-1: unknown): its last
  // change at or before the cycle's time stamp.
  std::vector<int64_t> levels(const std::string& name, uint64_t cycles, uint64_t periodPs) const {
    const auto code = codes.find(name);
    if (code == codes.end()) throw std::runtime_error("no signal " + name);
    std::vector<int64_t> out(cycles, -1);
    const auto found = changes_.find(code->second);
    if (found == changes_.end()) return out;
    const auto& list = found->second;
    size_t next = 0;
    int64_t level = -1;
    for (uint64_t cycle = 0; cycle < cycles; ++cycle) {
      while (next < list.size() && list[next].first <= cycle * periodPs) {
        level = list[next].second ? static_cast<int64_t>(*list[next].second) : -1;
        ++next;
      }
      out[cycle] = level;
    }
    return out;
  }

  // Every change of a signal: (time, value).
  const std::vector<std::pair<uint64_t, std::optional<uint64_t>>>& changes(
      const std::string& name) const {
    static const std::vector<std::pair<uint64_t, std::optional<uint64_t>>> none;
    const auto found = changes_.find(codes.at(name));
    return found == changes_.end() ? none : found->second;
  }

 private:
  void change(uint64_t time, const std::string& code, std::optional<uint64_t> value) {
    bool known = false;
    for (const auto& [name, c] : codes) known = known || c == code;
    if (!known) throw std::runtime_error("value change of undeclared code " + code);
    changes_[code].emplace_back(time, value);
  }

  std::map<std::string, std::vector<std::pair<uint64_t, std::optional<uint64_t>>>> changes_;
};

// A scratch directory removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = fs::temp_directory_path() /
            ("rtusim_vcd_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

// ---------------------------------------------------------------------------------------------
// Workload: a small frame of a procedural scene.

struct VcdWorkload {
  SvoBuild build;
  std::vector<TValueRecord> jobs;
  WordMemory memory() const { return build.image.memory(); }
};

VcdWorkload vcdWorkload(const std::string& name, int width, int height) {
  VcdWorkload s{buildSvo(*makeProceduralScene(name, 6)), {}};
  Camera camera;
  camera.width = width;
  camera.height = height;
  s.jobs = makeFrameJobs(camera, s.build.image.root);
  return s;
}

const VcdWorkload& sphere() {
  static const VcdWorkload scene = vcdWorkload("sphere", 8, 6);
  return scene;
}

struct Traced {
  RtuRun run;
  Vcd vcd;
  uint64_t periodPs;
  uint64_t horizon;  // cycles to look at: every result taken, plus a few

  std::vector<int64_t> levels(const std::string& name) const {
    return vcd.levels(name, horizon, periodPs);
  }
  // Cycles whose final valid and ready levels are both 1 on the channel `scope`.
  std::vector<uint64_t> transfers(const std::string& scope) const {
    const std::vector<int64_t> valid = levels(scope + ".valid"), ready = levels(scope + ".ready");
    std::vector<uint64_t> cycles;
    for (uint64_t t = 0; t < horizon; ++t)
      if (valid[t] == 1 && ready[t] == 1) cycles.push_back(t);
    return cycles;
  }
};

Traced traced(const VcdWorkload& scene, RtuConfig config, const TempDir& dir,
              const std::string& file, TraceOptions options = {}) {
  options.path = dir.file(file);
  config.trace = options;
  Traced t{simulateRtu(scene.memory(), scene.jobs, config), {}, 0, 0};
  t.vcd = Vcd::read(options.path);
  t.periodPs = static_cast<uint64_t>(1e6 / config.clockMhz + 0.5);
  t.horizon = t.run.totalCycles + 8;
  return t;
}

std::string core(int i) { return "rtu.core_" + std::to_string(i); }

// The cycle and core of every dispatch, in dispatch order. The job manager is a FIFO, so the
// k-th dispatch is job k.
struct Dispatch {
  uint64_t cycle;
  int core;
};

std::vector<Dispatch> dispatches(const Traced& t, int cores) {
  std::vector<Dispatch> all;
  for (int i = 0; i < cores; ++i)
    for (uint64_t cycle : t.transfers(core(i) + ".in")) all.push_back({cycle, i});
  std::sort(all.begin(), all.end(),
            [](const Dispatch& a, const Dispatch& b) { return a.cycle < b.cycle; });
  return all;
}

// Checks of every full trace against the run (ideal or cached memory, any policy).
void checkTrace(const Traced& t, int cores) {
  const RtuRun& run = t.run;
  const size_t rays = run.results.size();
  // In cycles where a cycle is a timescale (100 MHz: 10 ns), else in picoseconds.
  CHECK(t.vcd.timescale == (t.periodPs == 10000 ? "10ns" : "1ps"));
  for (uint64_t time : t.vcd.times) CHECK(time % t.periodPs == 0);

  // Host side: one job manager handshake per job, one result handshake per ray, in exactly the
  // cycles the host saw.
  const std::vector<uint64_t> accepted = t.transfers("rtu.job_manager.in");
  CHECK(accepted.size() == rays);
  if (!accepted.empty()) CHECK(accepted.front() == 0);
  const std::vector<uint64_t> out = t.transfers("rtu.result_manager.out");
  CHECK(out.size() == rays);
  CHECK(out == run.arrivalCycles);

  // Scheduler: its input handshakes are the core handshakes, one core per cycle.
  const std::vector<Dispatch> all = dispatches(t, cores);
  std::vector<uint64_t> dispatchCycles;
  for (const Dispatch& d : all) dispatchCycles.push_back(d.cycle);
  CHECK(t.transfers("rtu.scheduler.in") == dispatchCycles);
  // Cycles the job manager's output is valid and not taken are its stall cycles.
  {
    const std::vector<int64_t> valid = t.levels("rtu.scheduler.in.valid");
    const std::vector<int64_t> ready = t.levels("rtu.scheduler.in.ready");
    uint64_t stalled = 0;
    for (uint64_t c = 0; c < t.horizon; ++c)
      if (valid[c] == 1 && ready[c] != 1) ++stalled;
    CHECK(stalled == run.statistics.jobManagerStallCycles);
  }
  REQUIRE(all.size() == rays);
  // A job reaches the job manager's output at least 6 cycles after its host handshake.
  for (size_t k = 0; k < rays; ++k) CHECK(all[k].cycle >= accepted[k] + 6);

  // The result of job k: from core c_k, taken in a cycle with result_select = c_k, at least
  // cost + 2 cycles after the dispatch.
  // A core is occupied for the ray's cost (states) plus its cycles BLOCKED on memory.
  std::vector<uint64_t> arrivalOf(rays), occupiedOf(rays);
  for (size_t i = 0; i < rays; ++i) {
    arrivalOf[run.jobIndices[i]] = run.arrivalCycles[i];
    occupiedOf[run.jobIndices[i]] = resultCost(run.results[i]) + run.blockedCycles[i];
  }
  for (size_t k = 0; k < rays; ++k) {
    INFO("job " << k << " on core " << all[k].core << ", dispatched " << all[k].cycle);
    CHECK(arrivalOf[k] % static_cast<uint64_t>(cores) == static_cast<uint64_t>(all[k].core));
    CHECK(arrivalOf[k] >= all[k].cycle + occupiedOf[k] + 2);
  }

  for (int i = 0; i < cores; ++i) {
    INFO(core(i));
    const std::vector<int64_t> state = t.levels(core(i) + ".state");
    const std::vector<int64_t> inReady = t.levels(core(i) + ".in.ready");
    const std::vector<int64_t> outValid = t.levels(core(i) + ".out.valid");
    const std::vector<uint64_t> taken = t.transfers(core(i) + ".in");
    const std::vector<uint64_t> handed = t.transfers(core(i) + ".out");
    CHECK(taken.size() == run.statistics.coreTimes[static_cast<size_t>(i)].jobs);
    CHECK(handed.size() == taken.size());

    // IDLE -> INIT exactly in the cycles after a job handshake.
    std::set<uint64_t> takenSet(taken.begin(), taken.end());
    uint64_t badStart = 0, badLevel = 0;
    for (uint64_t c = 0; c + 1 < t.horizon; ++c) {
      const bool starts = state[c] == 0 && state[c + 1] == 1;
      if (starts != (takenSet.count(c) > 0)) ++badStart;
    }
    // in_ready = (state == IDLE), out_valid = (state == OUT), from cycle 0 to the end.
    for (uint64_t c = 0; c < t.horizon; ++c) {
      if (state[c] < 0 || state[c] > 7) ++badLevel;
      if ((inReady[c] == 1) != (state[c] == 0)) ++badLevel;
      if ((outValid[c] == 1) != (state[c] == 6)) ++badLevel;
    }
    CHECK(badStart == 0);
    CHECK(badLevel == 0);

    // State sequence, cycle by cycle, as src/kinds/svo/traversal_core.h steps it: INIT .. POP last
    // one cycle each; BLOCKED follows a memory read (EVAL, or PUSH through a far pointer) and ends
    // in the state after it; OUT waits for the result manager.
    const std::map<int64_t, std::set<int64_t>> successors = {
        {0, {0, 1}},    {1, {2}}, {2, {3, 4, 6, 7}}, {3, {2, 5, 6}},
        {4, {1, 6, 7}}, {5, {3}}, {6, {6, 0}},       {7, {7, 1, 3, 4, 6}}};
    uint64_t illegal = 0, blocked = 0;
    for (uint64_t c = 0; c + 1 < t.horizon; ++c) {
      const auto next = successors.find(state[c]);
      if (next == successors.end() || next->second.count(state[c + 1]) == 0) {
        ++illegal;
        UNSCOPED_INFO("cycle " << c << ": state " << state[c] << " -> " << state[c + 1]);
      }
      if (state[c] == 7) ++blocked;
    }
    CHECK(illegal == 0);
    // The core's time split (statistics) is the trace's count of cycles per state.
    const CoreStatistics& times = run.statistics.coreTimes[static_cast<size_t>(i)];
    uint64_t busy = 0, waiting = 0;
    for (uint64_t c = 0; c < run.totalCycles; ++c) {
      if (state[c] >= 1 && state[c] <= 5) ++busy;
      if (state[c] == 6) ++waiting;
    }
    CHECK(blocked == times.blockedCycles);
    CHECK(busy == times.busyCycles);
    CHECK(waiting == times.outCycles);
    // A result taken in k leaves the core IDLE in k + 1.
    for (uint64_t k : handed) CHECK(state[k + 1] == 0);

    // Each job: INIT in d + 1, then INIT .. POP and BLOCKED until OUT; that span is its cost.
    size_t job = 0;
    for (size_t k = 0; k < rays; ++k) {
      if (all[k].core != i) continue;
      const uint64_t d = all[k].cycle;
      uint64_t c = d + 1;
      while (c < t.horizon && state[c] != 6) {
        if (state[c] == 0) break;
        ++c;
      }
      INFO("job " << k << " dispatched in " << d);
      REQUIRE(c < t.horizon);
      CHECK(state[c] == 6);
      CHECK(c - (d + 1) == occupiedOf[k]);
      CHECK(handed[job] >= c);
      ++job;
    }

    // Stack depth stays within the RTL's 11 frames.
    for (int64_t depth : t.levels(core(i) + ".stack_depth")) CHECK(depth <= kRtlStackFrames);
  }

  // Result manager: the host takes a result in t from core t mod N, which handed it over
  // before t.
  std::vector<std::deque<uint64_t>> buffered(static_cast<size_t>(cores));
  for (int i = 0; i < cores; ++i)
    for (uint64_t k : t.transfers(core(i) + ".out")) buffered[static_cast<size_t>(i)].push_back(k);
  for (uint64_t when : out) {
    auto& queue = buffered[when % static_cast<uint64_t>(cores)];
    INFO("result taken in " << when);
    REQUIRE_FALSE(queue.empty());
    CHECK(queue.front() < when);
    queue.pop_front();
  }
  for (const auto& queue : buffered) CHECK(queue.empty());
}

}  // namespace

TEST_CASE("VCD of a two-core run shows every handshake and core state", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 2;
  const Traced t = traced(sphere(), config, dir, "full.vcd");
  REQUIRE(t.periodPs == 10000);  // 100 MHz

  for (const char* name :
       {"rtu.job_manager.in.valid", "rtu.job_manager.in.ready", "rtu.scheduler.in.valid",
        "rtu.scheduler.in.ready", "rtu.result_manager.out.valid", "rtu.result_manager.out.ready"})
    CHECK(t.vcd.has(name));
  for (int i = 0; i < 2; ++i)
    for (const char* name :
         {".state", ".stack_depth", ".in.valid", ".in.ready", ".out.valid", ".out.ready"})
      CHECK(t.vcd.has(core(i) + name));
  CHECK(t.vcd.widths.at("rtu.core_0.state") == 3);
  CHECK_FALSE(t.vcd.has("rtu.reorder_buffer.out.valid"));

  // The number of cycles with result_manager.out valid and ready equals the number of rays.
  CHECK(t.transfers("rtu.result_manager.out").size() == sphere().jobs.size());
  checkTrace(t, 2);

  // The sphere needs pushes: core 0's stack is used.
  const std::vector<int64_t> depth = t.levels("rtu.core_0.stack_depth");
  CHECK(*std::max_element(depth.begin(), depth.end()) > 0);
  // Ideal memory: never BLOCKED.
  for (int64_t state : t.levels("rtu.core_0.state")) CHECK(state != 7);
}

TEST_CASE("VCD shows each scheduling policy's choice of core", "[rtu]") {
  TempDir dir;
  const int cores = 4;
  for (SchedulerPolicy policy : {SchedulerPolicy::CyclicFirstAvailable, SchedulerPolicy::RoundRobin,
                                 SchedulerPolicy::FirstAvailable}) {
    RtuConfig config;
    config.cores = cores;
    config.scheduler = policy;
    INFO(toString(policy));
    const Traced t = traced(sphere(), config, dir, std::string(toString(policy)) + ".vcd");
    checkTrace(t, cores);

    const std::vector<Dispatch> all = dispatches(t, cores);
    std::vector<std::vector<int64_t>> ready;
    for (int i = 0; i < cores; ++i) ready.push_back(t.levels(core(i) + ".in.ready"));
    const std::vector<int64_t> pending = t.levels("rtu.scheduler.in.valid");
    std::set<uint64_t> dispatchCycles;
    for (const Dispatch& d : all) dispatchCycles.insert(d.cycle);

    for (size_t k = 0; k < all.size(); ++k) {
      const Dispatch& d = all[k];
      INFO("job " << k << " to core " << d.core << " in " << d.cycle);
      switch (policy) {
        case SchedulerPolicy::CyclicFirstAvailable:
          CHECK(static_cast<uint64_t>(d.core) == d.cycle % cores);
          break;
        case SchedulerPolicy::RoundRobin: CHECK(d.core == static_cast<int>(k % cores)); break;
        case SchedulerPolicy::FirstAvailable:
          for (int i = 0; i < d.core; ++i) CHECK(ready[static_cast<size_t>(i)][d.cycle] != 1);
          break;
      }
    }
    // No cycle in which the rule would dispatch the pending job goes by without a dispatch.
    int nextInLine = 0;
    uint64_t missed = 0;
    for (uint64_t c = 0; c < t.horizon; ++c) {
      if (pending[c] != 1) continue;
      bool due = false;
      switch (policy) {
        case SchedulerPolicy::CyclicFirstAvailable: due = ready[c % cores][c] == 1; break;
        case SchedulerPolicy::RoundRobin:
          due = ready[static_cast<size_t>(nextInLine)][c] == 1;
          break;
        case SchedulerPolicy::FirstAvailable:
          for (int i = 0; i < cores; ++i) due = due || ready[static_cast<size_t>(i)][c] == 1;
          break;
      }
      const bool dispatched = dispatchCycles.count(c) > 0;
      if (due != dispatched) ++missed;
      if (dispatched) nextInLine = (nextInLine + 1) % cores;
    }
    CHECK(missed == 0);
  }
}

TEST_CASE("VCD scope filter keeps only the scopes asked for", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 2;
  const Traced full = traced(sphere(), config, dir, "full.vcd");

  TraceOptions options;
  options.scopes = {"rtu.core_1"};
  const Traced only = traced(sphere(), config, dir, "core1.vcd", options);
  CHECK(only.run.arrivalCycles == full.run.arrivalCycles);
  CHECK(only.vcd.has("rtu.core_1.state"));
  CHECK(only.vcd.has("rtu.core_1.in.valid"));
  CHECK(only.vcd.has("rtu.core_1.out.ready"));
  for (const std::string& name : only.vcd.names()) {
    INFO(name);
    CHECK(name.rfind("rtu.core_1.", 0) == 0);
    // Kept signals are unchanged by the filter.
    CHECK(only.levels(name) == full.levels(name));
  }

  // A prefix is a scope, not a string prefix: rtu.core_1 does not keep rtu.core_10. With twelve
  // cores the instances are zero-padded (core_01), and the filter matches either spelling.
  RtuConfig twelve;
  twelve.cores = 12;
  const Traced many = traced(sphere(), twelve, dir, "twelve.vcd", options);
  CHECK(many.vcd.has("rtu.core_01.state"));
  for (const std::string& name : many.vcd.names()) {
    INFO(name);
    CHECK(name.rfind("rtu.core_01.", 0) == 0);
  }
  TraceOptions padded;
  padded.scopes = {"rtu.core_01"};
  CHECK(traced(sphere(), twelve, dir, "padded.vcd", padded).vcd.names() == many.vcd.names());

  // Several scopes, one of them the memory.
  RtuConfig cached = config;
  cached.memory = MemoryConfig{};
  options.scopes = {"rtu.core_1", "rtu.memory"};
  const Traced two = traced(sphere(), cached, dir, "two.vcd", options);
  CHECK(two.vcd.has("rtu.core_1.state"));
  CHECK(two.vcd.has("rtu.memory.l1_0.hits"));
  CHECK(two.vcd.has("rtu.memory.l2.misses"));
  CHECK_FALSE(two.vcd.has("rtu.core_0.state"));
  CHECK_FALSE(two.vcd.has("rtu.job_manager.in.valid"));
}

TEST_CASE("VCD scope that matches nothing is an error listing the scopes", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 4;
  TraceOptions options;
  options.path = dir.file("typo.vcd");
  for (const std::string scope : {"rtu.core_7", "rtu.schedular", "rtu.memory"}) {
    INFO(scope);
    options.scopes = {"rtu.core_1", scope};  // the ideal memory declares no signal
    config.trace = options;
    try {
      simulateRtu(sphere().memory(), sphere().jobs, config);
      FAIL("no error");
    } catch (const std::invalid_argument& error) {
      const std::string message = error.what();
      CHECK(message.find("'" + scope + "' matches no module") != std::string::npos);
      CHECK(message.find("rtu.core_3.in") != std::string::npos);
      CHECK(message.find("rtu.scheduler.in") != std::string::npos);
    }
  }
}

TEST_CASE("Trace signal classes keep only their signals, with the values of a full trace",
          "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 2;
  config.memory = MemoryConfig{};
  const Traced full = traced(sphere(), config, dir, "full.vcd");
  TraceOptions options;
  options.signalClasses = {"states", "caches"};
  const Traced some = traced(sphere(), config, dir, "some.vcd", options);
  CHECK(some.vcd.has("rtu.core_0.state"));
  CHECK(some.vcd.has("rtu.memory.l2.misses"));
  for (const std::string& name : some.vcd.names()) {
    INFO(name);
    const std::string leaf = name.substr(name.rfind('.') + 1);
    CHECK((leaf == "state" || leaf == "hits" || leaf == "misses"));
    CHECK(some.levels(name) == full.levels(name));
  }
  options.signalClasses = {"handshake"};
  CHECK_THROWS_WITH(traced(sphere(), config, dir, "typo.vcd", options),
                    Catch::Contains("'handshake' does not exist; the classes are handshakes"));
}

TEST_CASE("VCD window keeps only its cycles, with the values of a full trace", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 2;
  const Traced full = traced(sphere(), config, dir, "full.vcd");
  REQUIRE(full.run.totalCycles > 120);

  for (const auto& [from, to] :
       std::vector<std::pair<uint64_t, uint64_t>>{{30, 90}, {0, 7}, {100, 101}}) {
    TraceOptions options;
    options.fromCycle = from;
    options.toCycle = to;
    const Traced window = traced(sphere(), config, dir, "window.vcd", options);
    INFO("window [" << from << ", " << to << ")");
    REQUIRE_FALSE(window.vcd.times.empty());
    CHECK(window.vcd.times.front() == from * window.periodPs);
    for (uint64_t time : window.vcd.times) {
      CHECK(time >= from * window.periodPs);
      CHECK(time < to * window.periodPs);
    }
    CHECK(window.vcd.names() == full.vcd.names());
    for (const std::string& name : full.vcd.names()) {
      INFO(name);
      const std::vector<int64_t> a = full.levels(name), b = window.levels(name);
      CHECK(std::vector<int64_t>(a.begin() + static_cast<long>(from),
                                 a.begin() + static_cast<long>(to)) ==
            std::vector<int64_t>(b.begin() + static_cast<long>(from),
                                 b.begin() + static_cast<long>(to)));
    }
  }
}

TEST_CASE("VCD of cached memory: L1 and L2 counters and BLOCKED states", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 2;
  config.memory = MemoryConfig{};
  const Traced t = traced(sphere(), config, dir, "cached.vcd");
  checkTrace(t, 2);

  for (int i = 0; i < 2; ++i) {
    const std::string l1 = "rtu.memory.l1_" + std::to_string(i);
    REQUIRE(t.vcd.has(l1 + ".hits"));
    REQUIRE(t.vcd.has(l1 + ".misses"));
    const CacheStats& stats = t.run.statistics.l1[static_cast<size_t>(i)];
    for (const char* counter : {".hits", ".misses"}) {
      INFO(l1 << counter);
      const auto& changes = t.vcd.changes(l1 + counter);
      REQUIRE(changes.size() >= 2);
      // Unknown in $dumpvars until the first read, then counting up.
      uint64_t previous = 0;
      for (size_t c = 0; c < changes.size(); ++c) {
        const auto& [time, value] = changes[c];
        if (c == 0 && !value && time == 0) continue;
        REQUIRE(value.has_value());
        CHECK(*value >= previous);
        previous = *value;
      }
      CHECK(previous ==
            (counter == std::string(".hits") ? stats.hits + stats.merged : stats.misses));
      CHECK(previous > 0);
    }
  }
  const auto& l2 = t.vcd.changes("rtu.memory.l2.misses");
  REQUIRE_FALSE(l2.empty());
  CHECK(l2.back().second == t.run.statistics.l2.cache.misses);

  // Every read waits at least the L1 hit latency: core 0 is BLOCKED at some point.
  const std::vector<int64_t> state = t.levels("rtu.core_0.state");
  CHECK(std::count(state.begin(), state.end(), 7) > 0);
}

// A slow L1 wakes a core for the shared level several cycles after its read: the BLOCKED state
// must still reach the trace before those cycles are written. Flushing every cycle (the recorder
// refuses a record for a cycle already written) gives the file of a rarely flushed trace.
TEST_CASE("VCD streamed every cycle equals the VCD streamed rarely, with a slow L1", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 4;
  config.memory = MemoryConfig{};
  config.memory.l1.hitLatency = 4;
  TraceOptions everyCycle;
  everyCycle.flushCycles = 1;
  const Traced t = traced(sphere(), config, dir, "every.vcd", everyCycle);
  checkTrace(t, 4);
  const std::vector<int64_t> state = t.levels("rtu.core_0.state");
  CHECK(std::count(state.begin(), state.end(), 7) > 0);
  const Traced rarely = traced(sphere(), config, dir, "rarely.vcd");
  const auto text = [](const std::string& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  CHECK(text(dir.file("every.vcd")) == text(dir.file("rarely.vcd")));
}

TEST_CASE("VCD time stamps follow the clock", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 2;
  config.clockMhz = 250.0;  // 4 ns
  TraceOptions options;
  options.periodPs = 1;  // overridden by the clock
  const Traced t = traced(sphere(), config, dir, "fast.vcd", options);
  REQUIRE(t.periodPs == 4000);
  for (uint64_t time : t.vcd.times) CHECK(time % 4000 == 0);
  CHECK(t.vcd.times.back() / 4000 < t.run.totalCycles + 1);
  CHECK(t.transfers("rtu.result_manager.out") == t.run.arrivalCycles);

  // Same cycles as at 100 MHz: the clock changes only the time unit.
  RtuConfig slow = config;
  slow.clockMhz = 100.0;
  const Traced reference = traced(sphere(), slow, dir, "slow.vcd");
  CHECK(reference.run.arrivalCycles == t.run.arrivalCycles);
  for (const std::string& name : reference.vcd.names())
    CHECK(reference.levels(name) == t.levels(name));
}

TEST_CASE("VCD of a paced input link and of the reorder buffer", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 2;
  config.hostInput.bytesPerCycle = 3.0;
  config.reorderCapacity = 4;
  const Traced t = traced(sphere(), config, dir, "paced.vcd");
  // Records i < j cross no faster than 3 bytes per cycle (see test_rtu_configurations.cpp):
  // 3 (c_j - c_i) > 32 (j - i) - 3.
  const std::vector<uint64_t> accepted = t.transfers("rtu.job_manager.in");
  REQUIRE(accepted.size() == t.run.results.size());
  for (size_t i = 0; i + 1 < accepted.size(); ++i)
    for (size_t j = i + 1; j < accepted.size(); ++j)
      CHECK(3 * (accepted[j] - accepted[i]) + 3 > 32 * (j - i));
  // With the reorder buffer the host sees its output, in job order.
  REQUIRE(t.vcd.has("rtu.reorder_buffer.out.valid"));
  CHECK(t.transfers("rtu.reorder_buffer.out") == t.run.arrivalCycles);
  CHECK(t.transfers("rtu.result_manager.out").size() == t.run.results.size());
  std::vector<uint64_t> inOrder(t.run.results.size());
  for (size_t k = 0; k < inOrder.size(); ++k) inOrder[k] = k;
  CHECK(t.run.jobIndices == inOrder);
}

TEST_CASE("VCD errors: an empty window or an unwritable file", "[rtu]") {
  TempDir dir;
  RtuConfig config;
  config.cores = 2;
  TraceOptions options;
  options.path = dir.file("empty.vcd");
  options.fromCycle = 50;
  options.toCycle = 50;
  config.trace = options;
  CHECK_THROWS_AS(simulateRtu(sphere().memory(), sphere().jobs, config), std::invalid_argument);
  options = TraceOptions{};
  options.path = dir.file("no/such/directory/out.vcd");
  config.trace = options;
  CHECK_THROWS_AS(simulateRtu(sphere().memory(), sphere().jobs, config), std::runtime_error);
}

}  // namespace rtu
