#include "run/rtu_statistics.h"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <ostream>

#include "kinds/core_result.h"
#include "run/statistics_output.h"
#include "sim/ca/rtu_top.h"

namespace rtu {
namespace {

double ratio(uint64_t part, uint64_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

// Share of the run a host link spends moving records; an unlimited link moves one a cycle.
double linkUtilisation(uint64_t records, uint64_t recordBytes, double bytesPerCycle,
                       uint64_t cycles) {
  const double cyclesPerRecord =
      bytesPerCycle > 0 ? static_cast<double>(recordBytes) / bytesPerCycle : 1.0;
  return cycles == 0 ? 0.0 : std::min(1.0, records * cyclesPerRecord / cycles);
}

}  // namespace

RtuStatistics RtuStatistics::of(const RtuConfig& config) {
  RtuStatistics stats;
  stats.clockMhz = config.clockMhz;
  stats.cores = config.cores;
  stats.scheduler = toString(config.scheduler);
  stats.hostInBytesPerCycle = config.hostInput.bytesPerCycle;
  stats.hostOutBytesPerCycle = config.hostOutput.bytesPerCycle;
  stats.hostOutRecordBytes = config.outputLink().recordBytes;
  stats.warmFrames = config.warmFrames;
  stats.core = config.core;
  return stats;
}

void RtuStatistics::count(const CoreKindResult& result, uint64_t blocked) {
  const uint32_t cost = resultCost(result);
  totalCost += cost;
  maxCost = std::max<uint64_t>(maxCost, cost);
  belowResolution += resultBelowResolution(result);
  totalBlocked += blocked;
  maxBlocked = std::max(maxBlocked, blocked);
}

void RtuStatistics::addCounts(const RtuStatistics& other) {
  totalCost += other.totalCost;
  maxCost = std::max(maxCost, other.maxCost);
  belowResolution += other.belowResolution;
  totalBlocked += other.totalBlocked;
  maxBlocked = std::max(maxBlocked, other.maxBlocked);
}

double RtuStatistics::cyclesPerRay() const { return rays == 0 ? 0.0 : ratio(totalCycles, rays); }
double RtuStatistics::raysPerSecond() const {
  return totalCycles == 0
             ? 0.0
             : static_cast<double>(rays) * clockMhz * 1e6 / static_cast<double>(totalCycles);
}
double RtuStatistics::framesPerSecond() const {
  return totalCycles == 0 ? 0.0 : clockMhz * 1e6 / static_cast<double>(totalCycles);
}
double RtuStatistics::dramBytesPerCycle() const { return ratio(l2.dram.bytes, totalCycles); }
double RtuStatistics::simulatedRaysPerHostSecond() const {
  return hostSeconds > 0.0 ? static_cast<double>(rays) / hostSeconds : 0.0;
}
uint64_t RtuStatistics::idleCycles(const CoreStatistics& core) const {
  const uint64_t used =
      core.busyCycles + core.blockedCycles + core.outCycles + core.unitStallCycles;
  return totalCycles - std::min(totalCycles, used);
}

CacheStats RtuStatistics::allL1() const { return sumOf(l1); }
CoreStatistics RtuStatistics::allCores() const { return sumOf(coreTimes); }

int64_t RtuStatistics::waitBound() const {
  if (scheduler == "cfa") return cores - 1;
  if (scheduler == "fa") return 0;
  return -1;
}

RtuStatistics::CoreTimeShares RtuStatistics::coreTimeShares() const {
  const CoreStatistics total = allCores();
  const uint64_t all = totalCycles * coreTimes.size();
  const uint64_t used =
      total.busyCycles + total.blockedCycles + total.outCycles + total.unitStallCycles;
  return {ratio(total.busyCycles, all), ratio(total.blockedCycles, all),
          ratio(total.outCycles, all), ratio(all - std::min(all, used), all),
          ratio(total.unitStallCycles, all)};
}

double RtuStatistics::frameMilliseconds() const {
  return static_cast<double>(totalCycles) / (clockMhz * 1e3);
}

RtuStatistics::Utilisation RtuStatistics::utilisation() const {
  const CoreTimeShares shares = coreTimeShares();
  Utilisation use;
  use.cores = shares.busy;
  use.memoryLatency = shares.blocked;
  // The DRAM's data bus and the L2's port, one request a cycle (sim/memory/l2_cache_timing.h).
  use.dramBandwidth = idealMemory ? 0.0 : ratio(l2.dram.busyCycles, totalCycles);
  use.l2Port = idealMemory ? 0.0 : ratio(l2.cache.accesses, totalCycles);
  if (hostInBytesPerCycle > 0)
    use.hostIn = linkUtilisation(rays, kHostRecordBytes, hostInBytesPerCycle, totalCycles);
  if (hostOutBytesPerCycle > 0)
    use.hostOut = linkUtilisation(rays, hostOutRecordBytes, hostOutBytesPerCycle, totalCycles);
  // The job manager and scheduler issue at most one job a cycle.
  use.jobManager = ratio(rays, totalCycles);
  return use;
}

namespace {

// The utilisations by name, the highest first (the first in declaration order among equals).
std::vector<std::pair<std::string, double>> ranked(const RtuStatistics::Utilisation& utilisation) {
  std::vector<std::pair<std::string, double>> all;
  for (const auto& [name, value] : statisticValues(utilisation))
    all.emplace_back(name, std::get<double>(value));
  std::stable_sort(all.begin(), all.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  return all;
}

std::string percent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f %%", 100 * share);
  return text;
}

}  // namespace

std::string RtuStatistics::limit() const {
  const auto all = ranked(utilisation());
  return all.front().second >= kSaturated ? all.front().first : "none";
}

double RtuStatistics::limitUtilisation() const { return ranked(utilisation()).front().second; }

std::string RtuStatistics::cacheStart() const {
  if (warmFrames == 0) return "cold";
  return "warm after " + std::to_string(warmFrames) + (warmFrames == 1 ? " frame" : " frames");
}

std::string RtuStatistics::describeLimit() const {
  const auto all = ranked(utilisation());
  const auto& [name, value] = all.front();
  if (value < kSaturated) return "nothing saturated (highest: " + name + " " + percent(value) + ")";
  // A runner-up within 5 points could swap places with a small change: named with it.
  const auto& [second, secondValue] = all[1];
  if (value - secondValue < 0.05)
    return "limited by " + name + " (" + percent(value) + "; " + second + " " +
           percent(secondValue) + " close behind)";
  return "limited by " + name + " (" + percent(value) + ")";
}

const StatisticGroup<RtuStatistics::CoreTimeShares>& RtuStatistics::CoreTimeShares::declaration() {
  static const StatisticGroup<CoreTimeShares> group =
      StatisticGroup<CoreTimeShares>("shares of the cores' time")
          .derived(Statistic("busy", "", "share of the cores' cycles busy"), &CoreTimeShares::busy)
          .derived(Statistic("blocked", "", "share BLOCKED on memory"), &CoreTimeShares::blocked)
          .derived(Statistic("handover", "", "share in OUT"), &CoreTimeShares::handover)
          .derived(Statistic("idle", "", "share in IDLE"), &CoreTimeShares::idle)
          .derived(Statistic("triangle_unit_stall", "",
                             "share waiting for a shared ray/triangle unit"),
                   &CoreTimeShares::unitStall);
  return group;
}

const StatisticGroup<RtuStatistics::Utilisation>& RtuStatistics::Utilisation::declaration() {
  static const StatisticGroup<Utilisation> group =
      StatisticGroup<Utilisation>("utilisation of what can bound the frame rate")
          .derived(Statistic("cores", "", "share of the cores' time busy"), &Utilisation::cores)
          .derived(Statistic("memory_latency", "",
                             "share of the cores' time BLOCKED waiting for memory reads"),
                   &Utilisation::memoryLatency)
          .derived(Statistic("dram_bandwidth", "",
                             "share of the run the DRAM's data bus transfers (0: ideal memory)"),
                   &Utilisation::dramBandwidth)
          .derived(Statistic("l2_port", "",
                             "L2 requests per cycle: its port accepts one a cycle (0: ideal "
                             "memory)"),
                   &Utilisation::l2Port)
          .derived(Statistic("host_in", "",
                             "share of the run the input link moves records (0: unlimited link)"),
                   &Utilisation::hostIn)
          .derived(Statistic("host_out", "",
                             "share of the run the output link moves records (0: unlimited link)"),
                   &Utilisation::hostOut)
          .derived(
              Statistic(
                  "job_manager", "",
                  "jobs issued per cycle: the job manager and scheduler issue one a cycle at most"),
              &Utilisation::jobManager);
  return group;
}

const StatisticGroup<RtuStatistics>& RtuStatistics::declaration() {
  using S = RtuStatistics;
  using Core = PartOf<S, CoreStatistics>;
  static const StatisticGroup<Core> coreLayout =
      StatisticGroup<Core>("a core of the run")
          .derived(Statistic("core", "", "the core's number"),
                   [](const Core& c) { return c.index; })
          .own<S, CoreStatistics>()
          .derived(Statistic("idle", "cycles",
                             "cycles in IDLE: the run's cycles less busy, blocked and handover"),
                   [](const Core& c) { return c.whole.idleCycles(c.values); })
          .computed<CacheStats>(Statistic("l1", "", "the core's L1 (cached memory)"),
                                [](const Core& c) { return c.whole.l1[c.index]; })
          .writtenWhen(
              [](const Core& c) { return !c.whole.idealMemory && c.index < c.whole.l1.size(); });
  const auto cached = [](const S& s) { return !s.idealMemory; };
  static const StatisticGroup<S> group =
      StatisticGroup<S>("a run: --stats files, \"statistics\" of fps and sweep rows")
          .count(Statistic("rays", "rays", "results the host received"), &S::rays)
          .count(
              Statistic("total_cycles", "cycles",
                        "from the first cycle after reset to the cycle the last result is taken"),
              &S::totalCycles)
          .derived(Statistic("cycles_per_ray", "cycles", "total_cycles / rays"), &S::cyclesPerRay)
          .setting(Statistic("clock_mhz", "MHz", "the clock of rates and frame times"),
                   &S::clockMhz)
          .derived(Statistic("frame_ms", "ms",
                             "total_cycles at the clock: the run's rays as one frame"),
                   &S::frameMilliseconds)
          .derived(Statistic("fps", "frames/s", "frames per second at the clock"),
                   &S::framesPerSecond)
          .derived(Statistic("rays_per_second", "rays/s", "rays per second at the clock"),
                   &S::raysPerSecond)
          .derived(Statistic("limit", "",
                             "the resource of the highest utilisation, when it reaches 0.8; "
                             "none below (docs/exploration.md, §2)"),
                   &S::limit)
          .derived(Statistic("limit_utilisation", "", "the highest utilisation, saturated or not"),
                   &S::limitUtilisation)
          .computed<Utilisation>(Statistic("utilisation", "", ""), &S::utilisation)
          .derived(Statistic("cost/mean", "cycles",
                             "per ray: cycles a core spends on it outside IDLE, OUT and BLOCKED "
                             "(its traversal's states)"),
                   [](const S& s) { return ratio(s.totalCost, s.rays); })
          .maximum(Statistic("cost/max", "cycles", "the costliest ray's cost"), &S::maxCost)
          .count(Statistic("cost/total", "cycles", "the rays' costs summed"), &S::totalCost)
          .derived(Statistic("blocked_cycles/mean", "cycles",
                             "per ray: cycles BLOCKED on memory, beside the cost"),
                   [](const S& s) { return ratio(s.totalBlocked, s.rays); })
          .maximum(Statistic("blocked_cycles/max", "cycles", "the most a ray was blocked"),
                   &S::maxBlocked)
          .count(Statistic("blocked_cycles/total", "cycles", "the rays' blocked cycles summed"),
                 &S::totalBlocked)
          .computed<CoreTimeShares>(Statistic("core_time", "", ""), &S::coreTimeShares)
          .list(Statistic("cores", "", "per core"), &S::coreTimes, &coreLayout)
          .extend(CoreKinds::runCounters<S>([](const S& s) { return s.core; },
                                            [](const S& s) { return s.allCores(); }))
          .combinedOnly(&S::l1)
          .count(Statistic(
                     "below_resolution", "rays",
                     "rays that reached nodes narrower than a step of the format (result flag 4)")
                     .reportedWhenNotZero("nodes narrower than a step; flag 4"),
                 &S::belowResolution)
          .count(Statistic("job_manager/stall_cycles", "cycles",
                           "cycles the job manager's output was valid and not taken"),
                 &S::jobManagerStallCycles)
          .setting(Statistic("scheduler/policy", "", "cfa, fa or rr"), &S::scheduler)
          .histogram(Statistic("scheduler/wait_histogram", "jobs",
                               "jobs by their wait from pending to dispatch (index: cycles)"),
                     &S::waitHistogram)
          .maximum(Statistic("scheduler/max_wait", "cycles",
                             "the longest wait from pending to dispatch"),
                   &S::maxWait)
          .maximum(Statistic("scheduler/max_wait_with_ready_core", "cycles",
                             "the longest wait of a job that found a core ready (eq. 6.7's case)"),
                   &S::maxWaitWithReadyCore)
          .derived(Statistic("scheduler/eq_6_7_bound", "cycles",
                             "the thesis' worst-case wait (eq. 6.7) for the policy; W_J for rr"),
                   [](const S& s) {
                     return s.waitBound() < 0 ? StatisticValue("W_J")
                                              : StatisticValue(s.waitBound());
                   })
          .maximum(Statistic("result_manager/max_buffers_full", "buffers",
                             "the most result buffers full at once"),
                   &S::resultBuffersMaxFull)
          .setting(Statistic("memory/kind", "", "ideal or cached"),
                   [](const S& s) { return s.idealMemory ? "ideal" : "cached"; })
          .setting(Statistic("memory/caches", "",
                             "cold, or warm after N frames of the same rays (warm_frames)"),
                   [](const S& s) { return s.cacheStart(); })
          .writtenWhen(cached)
          .computed<CacheStats>(Statistic("memory/l1", "", "the L1s summed"), &S::allL1)
          .writtenWhen(cached)
          .group(Statistic("memory", "", ""), &S::l2)
          .writtenWhen(cached)
          .derived(Statistic("memory/dram/bytes_per_cycle", "bytes/cycle",
                             "DRAM bytes per cycle of the run"),
                   &S::dramBytesPerCycle)
          .writtenWhen(cached)
          .derived(Statistic("memory/dram/bandwidth_mb_per_second", "MB/s",
                             "DRAM bytes per second at the clock"),
                   [](const S& s) { return s.dramBytesPerCycle() * s.clockMhz; })
          .writtenWhen(cached)
          .setting(Statistic("simulation/model", "",
                             "what answered: systemc, recurrence, lt, golden or sampled"),
                   &S::model)
          .real(Statistic("simulation/host_seconds", "s",
                          "host time of the run (differs run to run)"),
                &S::hostSeconds)
          .derived(Statistic("simulation/rays_per_host_second", "rays/s", "rays per host second"),
                   &S::simulatedRaysPerHostSecond)
          .maximum(Statistic("reorder_buffer/max_occupancy", "results",
                             "the most results the reorder buffer held (written when not 0)"),
                   &S::reorderMaxOccupancy)
          .writtenWhen([](const S& s) { return s.reorderMaxOccupancy > 0; })
          .group(Statistic("scene_manager", "", "a run through the scene manager"), &S::scene);
  return group;
}

nlohmann::ordered_json RtuStatistics::toJson() const { return statisticsJson(*this); }

namespace {

// How the report's last line names what answered.
std::string answeredBy(const std::string& model) {
  if (model == "systemc") return "simulated in ";
  if (model == "lt") return "estimated by the loosely-timed model (docs/fidelity.md) in ";
  if (model == "golden") return "golden costs in the recurrence, memory as ideal, in ";
  return "answered by the " + model + " in ";
}

}  // namespace

void RtuStatistics::writeReport(std::ostream& out) const {
  out << std::fixed << std::setprecision(2);
  out << "rays " << rays << ", total cycles " << totalCycles << " (" << cyclesPerRay()
      << " per ray)\n";
  out << "at " << clockMhz << " MHz: " << raysPerSecond() / 1e6 << " M rays/s, frame "
      << frameMilliseconds() << " ms, " << framesPerSecond() << " frames/s, " << describeLimit()
      << "\n";
  out << "per ray: cost " << ratio(totalCost, rays) << " states (max " << maxCost << "), blocked "
      << ratio(totalBlocked, rays) << " cycles (max " << maxBlocked << ")\n";
  const CoreTimeShares shares = coreTimeShares();
  out << "core time (" << cores << " cores): busy " << 100 * shares.busy << " %, blocked "
      << 100 * shares.blocked << " %, handover " << 100 * shares.handover << " %, idle "
      << 100 * shares.idle << " %\n";
  if (const uint64_t stalls = allCores().unitStallCycles; stalls > 0)
    out << "triangle units shared: tests waited " << stalls << " cycles (" << ratio(stalls, rays)
        << " per ray)\n";
  out << "scheduler " << scheduler << ": max wait " << maxWait << " cycles, "
      << maxWaitWithReadyCore << " with a core ready (eq. 6.7 bound: "
      << (waitBound() < 0 ? std::string("W_J") : std::to_string(waitBound())) << ")\n";
  if (!idealMemory) {
    const CacheStats l1Total = allL1();
    out << "L1 hit rate " << 100 * hitRate(l1Total) << " % of " << l1Total.accesses
        << " reads; L2 hit rate " << 100 * hitRate(l2.cache) << " % of " << l2.cache.accesses
        << "; DRAM " << l2.dram.bytes << " bytes (" << dramBytesPerCycle() << " B/cycle, "
        << dramBytesPerCycle() * clockMhz << " MB/s), caches " << cacheStart() << "\n";
  }
  if (scene)
    out << "scene manager: " << ratio(scene->jobs, scene->rays) << " jobs per ray, "
        << scene->culled << " instances culled, " << scene->earlyTerminations
        << " early terminations (" << scene->skipped << " instances skipped)\n";
  writeReportedLines(out, *this);
  out << answeredBy(model) << hostSeconds << " s (" << simulatedRaysPerHostSecond() / 1e6
      << " M rays per host second)\n";
}

RtuStatistics collectStatistics(const RtuTop& top, const RtuConfig& config, uint64_t totalCycles) {
  RtuStatistics stats = RtuStatistics::of(config);
  stats.rays = top.sink().received();
  stats.totalCycles = totalCycles;
  for (const auto& core : top.cores()) stats.coreTimes.push_back(core->statistics());
  const HostSink::Arrivals& arrivals = top.sink().arrivals();
  for (size_t i = 0; i < arrivals.results.size(); ++i)
    stats.count(arrivals.results[i], arrivals.blockedCycles[i]);
  stats.jobManagerStallCycles = top.jobManager().statistics().stallCycles;
  const SchedulerStatistics scheduler = top.scheduler().statistics();
  stats.waitHistogram = scheduler.waitHistogram;
  stats.maxWait = scheduler.maxWait;
  stats.maxWaitWithReadyCore = scheduler.maxWaitWithReadyCore;
  stats.resultBuffersMaxFull = top.resultManager().statistics().maxBuffered;
  if (top.reorderBuffer())
    stats.reorderMaxOccupancy = top.reorderBuffer()->statistics().maxOccupancy;
  if (top.sceneManager()) stats.scene = top.sceneManager()->statistics();
  stats.idealMemory = top.memory().combinational();
  if (!stats.idealMemory) {
    for (int i = 0; i < config.cores; ++i) stats.l1.push_back(top.memory().l1Statistics(i));
    stats.l2 = top.memory().l2Statistics();
  }
  return stats;
}

}  // namespace rtu
