#include "run/rtu_statistics.h"

#include <algorithm>
#include <iomanip>
#include <ostream>

#include "sim/ca/rtu_top.h"

namespace rtu {
namespace {

double ratio(uint64_t part, uint64_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

nlohmann::ordered_json cacheJson(const CacheStats& stats) {
  return {{"accesses", stats.accesses}, {"hits", stats.hits},       {"merged", stats.merged},
          {"misses", stats.misses},     {"evictions", stats.evictions},
          {"hit_rate", hitRate(stats)}};
}

}  // namespace

double RtuStatistics::cyclesPerRay() const { return rays == 0 ? 0.0 : ratio(totalCycles, rays); }
double RtuStatistics::raysPerSecond() const {
  return totalCycles == 0 ? 0.0 : static_cast<double>(rays) * clockMhz * 1e6 / static_cast<double>(totalCycles);
}
double RtuStatistics::framesPerSecond() const {
  return totalCycles == 0 ? 0.0 : clockMhz * 1e6 / static_cast<double>(totalCycles);
}
double RtuStatistics::dramBytesPerCycle() const { return ratio(l2.dram.bytes, totalCycles); }
double RtuStatistics::simulatedRaysPerHostSecond() const {
  return hostSeconds > 0.0 ? static_cast<double>(rays) / hostSeconds : 0.0;
}
uint64_t RtuStatistics::idleCycles(const CoreStatistics& core) const {
  return totalCycles - std::min(totalCycles, core.busyCycles + core.blockedCycles + core.outCycles);
}
double hitRate(const CacheStats& stats) { return ratio(stats.hits + stats.merged, stats.accesses); }

CacheStats RtuStatistics::allL1() const {
  CacheStats total;
  for (const CacheStats& s : l1) {
    total.accesses += s.accesses;
    total.hits += s.hits;
    total.merged += s.merged;
    total.misses += s.misses;
    total.evictions += s.evictions;
  }
  return total;
}

CoreStatistics RtuStatistics::allCores() const {
  CoreStatistics total;
  for (const CoreStatistics& c : coreTimes) {
    total.jobs += c.jobs;
    total.busyCycles += c.busyCycles;
    total.blockedCycles += c.blockedCycles;
    total.outCycles += c.outCycles;
    total.stackOverflows += c.stackOverflows;
    total.tOverflows += c.tOverflows;
  }
  return total;
}

int64_t RtuStatistics::waitBound() const {
  if (scheduler == "cfa") return cores - 1;
  if (scheduler == "fa") return 0;
  return -1;
}

std::vector<uint64_t> RtuStatistics::waitHistogramArray() const {
  std::vector<uint64_t> histogram(waitHistogram.empty() ? 0 : waitHistogram.rbegin()->first + 1);
  for (const auto& [wait, jobs] : waitHistogram) histogram[wait] = jobs;
  return histogram;
}

RtuStatistics::CoreTimeShares RtuStatistics::coreTimeShares() const {
  const CoreStatistics total = allCores();
  const uint64_t all = totalCycles * coreTimes.size();
  const uint64_t used = total.busyCycles + total.blockedCycles + total.outCycles;
  return {ratio(total.busyCycles, all), ratio(total.blockedCycles, all),
          ratio(total.outCycles, all), ratio(all - std::min(all, used), all)};
}

double RtuStatistics::frameMilliseconds() const {
  return static_cast<double>(totalCycles) / (clockMhz * 1e3);
}

namespace {

nlohmann::ordered_json sceneJson(const SceneManagerStatistics& scene) {
  nlohmann::ordered_json perRay = nlohmann::ordered_json::object();
  for (const auto& [jobs, rays] : scene.jobsPerRay) perRay[std::to_string(jobs)] = rays;
  return {{"rays", scene.rays},
          {"jobs", scene.jobs},
          {"jobs_per_ray", scene.rays == 0 ? 0.0 : static_cast<double>(scene.jobs) / scene.rays},
          {"jobs_per_ray_histogram", perRay},
          {"instances_culled", scene.culled},
          {"early_terminations", scene.earlyTerminations},
          {"instances_skipped", scene.skipped}};
}

// Share of the run a host link spends moving records; an unlimited link moves one a cycle.
double linkUtilisation(uint64_t records, uint64_t recordBytes, double bytesPerCycle,
                       uint64_t cycles) {
  const double cyclesPerRecord =
      bytesPerCycle > 0 ? static_cast<double>(recordBytes) / bytesPerCycle : 1.0;
  return cycles == 0 ? 0.0 : std::min(1.0, records * cyclesPerRecord / cycles);
}

}  // namespace

std::vector<std::pair<std::string, double>> RtuStatistics::utilisation() const {
  const CoreTimeShares shares = coreTimeShares();
  // The job manager and scheduler issue at most one job a cycle.
  const double issue = totalCycles == 0 ? 0.0 : ratio(rays, totalCycles);
  const double hostIn = linkUtilisation(rays, kHostRecordBytes, hostInBytesPerCycle, totalCycles);
  const double hostOut = linkUtilisation(rays, hostOutRecordBytes, hostOutBytesPerCycle, totalCycles);
  return {{"cores", shares.busy},
          {"memory", shares.blocked},
          {"host_in", hostInBytesPerCycle > 0 ? hostIn : 0.0},
          {"host_out", hostOutBytesPerCycle > 0 ? hostOut : 0.0},
          {"job_manager", issue}};
}

std::string RtuStatistics::limit() const {
  const auto all = utilisation();
  return std::max_element(all.begin(), all.end(),
                          [](const auto& a, const auto& b) { return a.second < b.second; })
      ->first;
}

nlohmann::ordered_json RtuStatistics::toJson() const {
  using json = nlohmann::ordered_json;
  json coresJson = json::array();
  for (size_t i = 0; i < coreTimes.size(); ++i) {
    const CoreStatistics& c = coreTimes[i];
    json core = {{"core", i},           {"jobs", c.jobs},
                 {"busy", c.busyCycles}, {"blocked", c.blockedCycles},
                 {"handover", c.outCycles}, {"idle", idleCycles(c)}};
    if (!idealMemory) core["l1"] = cacheJson(l1[i]);
    coresJson.push_back(core);
  }
  const CoreTimeShares shares = coreTimeShares();
  json utilisationJson = json::object();
  for (const auto& [resource, value] : utilisation()) utilisationJson[resource] = value;
  json result = {
      {"rays", rays},
      {"total_cycles", totalCycles},
      {"cycles_per_ray", cyclesPerRay()},
      {"clock_mhz", clockMhz},
      {"frame_ms", frameMilliseconds()},
      {"fps", framesPerSecond()},
      {"rays_per_second", raysPerSecond()},
      {"limit", limit()},
      {"utilisation", utilisationJson},
      {"cost", {{"mean", ratio(totalCost, rays)}, {"max", maxCost}, {"total", totalCost}}},
      {"blocked_cycles", {{"mean", ratio(totalBlocked, rays)}, {"max", maxBlocked}, {"total", totalBlocked}}},
      {"core_time",
       {{"busy", shares.busy}, {"blocked", shares.blocked}, {"handover", shares.handover},
        {"idle", shares.idle}}},
      {"cores", coresJson},
      {"stack_overflows", stackOverflows},
      {"t_overflows", allCores().tOverflows},
      {"below_resolution", belowResolution},
      {"job_manager", {{"stall_cycles", jobManagerStallCycles}}},
      {"scheduler",
       {{"policy", scheduler},
        {"wait_histogram", waitHistogramArray()},
        {"max_wait", maxWait},
        {"max_wait_with_ready_core", maxWaitWithReadyCore},
        {"eq_6_7_bound", waitBound() < 0 ? json("W_J") : json(waitBound())}}},
      {"result_manager", {{"max_buffers_full", resultBuffersMaxFull}}},
      {"memory", {{"kind", idealMemory ? "ideal" : "cached"}}},
      {"simulation", {{"model", model},
                      {"host_seconds", hostSeconds},
                      {"rays_per_host_second", simulatedRaysPerHostSecond()}}}};
  if (reorderMaxOccupancy > 0) result["reorder_buffer"] = {{"max_occupancy", reorderMaxOccupancy}};
  if (scene) result["scene_manager"] = sceneJson(*scene);
  if (!idealMemory) {
    result["memory"]["l1"] = cacheJson(allL1());
    result["memory"]["l2"] = cacheJson(l2.cache);
    result["memory"]["l2"]["port_queue_cycles"] = l2.portQueueCycles;
    result["memory"]["l2"]["mshr_queue_cycles"] = l2.mshrQueueCycles;
    result["memory"]["dram"] = {{"reads", l2.dram.reads},
                                {"bytes", l2.dram.bytes},
                                {"busy_cycles", l2.dram.busyCycles},
                                {"bytes_per_cycle", dramBytesPerCycle()},
                                {"bandwidth_mb_per_second", dramBytesPerCycle() * clockMhz}};
  }
  return result;
}

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
      << frameMilliseconds() << " ms, " << framesPerSecond() << " frames/s, limited by "
      << limit() << "\n";
  out << "per ray: cost " << ratio(totalCost, rays) << " states (max " << maxCost
      << "), blocked " << ratio(totalBlocked, rays) << " cycles (max " << maxBlocked << ")\n";
  const CoreTimeShares shares = coreTimeShares();
  out << "core time (" << cores << " cores): busy " << 100 * shares.busy << " %, blocked "
      << 100 * shares.blocked << " %, handover " << 100 * shares.handover << " %, idle "
      << 100 * shares.idle << " %\n";
  out << "scheduler " << scheduler << ": max wait " << maxWait << " cycles, "
      << maxWaitWithReadyCore << " with a core ready (eq. 6.7 bound: "
      << (waitBound() < 0 ? std::string("W_J") : std::to_string(waitBound())) << ")\n";
  if (!idealMemory) {
    const CacheStats l1Total = allL1();
    out << "L1 hit rate " << 100 * hitRate(l1Total) << " % of " << l1Total.accesses
        << " reads; L2 hit rate " << 100 * hitRate(l2.cache) << " % of "
        << l2.cache.accesses << "; DRAM " << l2.dram.bytes << " bytes ("
        << dramBytesPerCycle() << " B/cycle, " << dramBytesPerCycle() * clockMhz << " MB/s)\n";
  }
  if (scene)
    out << "scene manager: " << ratio(scene->jobs, scene->rays) << " jobs per ray, "
        << scene->culled << " instances culled, " << scene->earlyTerminations
        << " early terminations (" << scene->skipped << " instances skipped)\n";
  if (stackOverflows > 0) out << "stack overflows: " << stackOverflows << " rays\n";
  if (const uint64_t wrapped = allCores().tOverflows)
    out << "t overflows: " << wrapped << " rays (t-values beyond the fixed-point range; flag 2)\n";
  if (belowResolution > 0)
    out << "below resolution: " << belowResolution << " rays (nodes narrower than a step; flag 4)\n";
  out << answeredBy(model) << hostSeconds << " s (" << simulatedRaysPerHostSecond() / 1e6
      << " M rays per host second)\n";
}

RtuStatistics collectStatistics(const RtuTop& top, const RtuConfig& config, uint64_t totalCycles) {
  RtuStatistics stats;
  stats.rays = top.sink().arrivals().size();
  stats.totalCycles = totalCycles;
  stats.clockMhz = config.clockMhz;
  stats.cores = config.cores;
  stats.scheduler = toString(config.scheduler);
  for (const auto& core : top.cores()) stats.coreTimes.push_back(core->statistics());
  stats.stackOverflows = stats.allCores().stackOverflows;
  const HostSink::Arrivals& arrivals = top.sink().arrivals();
  for (const TraversalResult& result : arrivals.results) {
    stats.totalCost += result.cost;
    stats.maxCost = std::max<uint64_t>(stats.maxCost, result.cost);
    stats.belowResolution += result.belowResolution;
  }
  for (uint32_t blocked : arrivals.blockedCycles) {
    stats.totalBlocked += blocked;
    stats.maxBlocked = std::max<uint64_t>(stats.maxBlocked, blocked);
  }
  stats.hostInBytesPerCycle = config.hostInput.bytesPerCycle;
  stats.hostOutBytesPerCycle = config.hostOutput.bytesPerCycle;
  stats.hostOutRecordBytes = config.outputLink().recordBytes;
  stats.jobManagerStallCycles = top.jobManager().statistics().stallCycles;
  const SchedulerStatistics scheduler = top.scheduler().statistics();
  stats.waitHistogram = scheduler.waitHistogram;
  stats.maxWait = scheduler.maxWait;
  stats.maxWaitWithReadyCore = scheduler.maxWaitWithReadyCore;
  stats.resultBuffersMaxFull = top.resultManager().statistics().maxBuffered;
  if (top.reorderBuffer()) stats.reorderMaxOccupancy = top.reorderBuffer()->statistics().maxOccupancy;
  if (top.sceneManager()) stats.scene = top.sceneManager()->statistics();
  stats.idealMemory = top.memory().combinational();
  if (!stats.idealMemory) {
    for (int i = 0; i < config.cores; ++i) stats.l1.push_back(top.memory().l1Statistics(i));
    stats.l2 = top.memory().l2Statistics();
  }
  return stats;
}

}  // namespace rtu
