#include "rtu_options.h"

#include <fstream>
#include <iostream>
#include <stdexcept>


namespace rtu {
namespace {

void addCacheOptions(CLI::App& command, const std::string& level, CacheConfig& cache) {
  const std::string prefix = "--" + level + "-";
  const std::string name = level == "l1" ? "L1" : "L2";
  command.add_option(prefix + "size", cache.sizeBytes, name + " size in bytes")->capture_default_str();
  command.add_option(prefix + "line", cache.lineBytes, name + " line size in bytes")->capture_default_str();
  command.add_option(prefix + "ways", cache.ways, name + " associativity")->capture_default_str();
  command
      .add_option_function<std::string>(
          prefix + "replacement",
          [&cache](const std::string& text) { cache.replacement = parseReplacement(text); },
          name + " replacement: lru, fifo or random")
      ->check(CLI::IsMember({"lru", "fifo", "random"}));
  command.add_option(prefix + "latency", cache.hitLatency, name + " hit latency in cycles")
      ->capture_default_str();
  command.add_option(prefix + "mshrs", cache.maxOutstandingMisses, name + " outstanding-miss limit")
      ->capture_default_str();
}

}  // namespace

void addRtuOptions(CLI::App& command, RtuOptions& options) {
  RtuConfig& config = options.config;
  command.add_option("--cores", config.cores, "number of traversal cores")->capture_default_str();
  command
      .add_option_function<std::string>(
          "--scheduler",
          [&config](const std::string& name) { config.scheduler = parseSchedulerPolicy(name); },
          "cfa (cyclic first-available, the RTL), rr (round-robin) or fa (first-available)")
      ->check(CLI::IsMember({"cfa", "rr", "fa"}));
  command.add_option("--memory", options.memory, "ideal (thesis ROM) or cached (L1, L2, DRAM)")
      ->capture_default_str()
      ->check(CLI::IsMember({"ideal", "cached"}));
  addCacheOptions(command, "l1", config.memory.l1);
  addCacheOptions(command, "l2", config.memory.l2);
  command.add_option("--dram-latency", config.memory.dram.latency, "DRAM latency in cycles")
      ->capture_default_str();
  command.add_option("--dram-bytes-per-cycle", config.memory.dram.bytesPerCycle,
                     "DRAM bandwidth in bytes per cycle")
      ->capture_default_str();
  command.add_option("--jm-stages", config.jobManager.stages,
                     "job manager pipeline stages for t-value records (RTL: 6)")
      ->capture_default_str();
  command.add_option("--jm-ray-stages", config.jobManager.rayStages,
                     "extra stages for ray records: transform and t-parameters")
      ->capture_default_str();
  command.add_option("--jm-header-fetch", config.jobManager.headerFetchCycles,
                     "cycles to fetch a model header, once per model")
      ->capture_default_str();
  command.add_option("--reorder", config.reorderCapacity,
                     "reorder buffer of this many results: results in submission order (0: none)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  command.add_option("--host-in-bytes-per-cycle", config.hostInput.bytesPerCycle,
                     "host input link rate (thesis DMA: about 3; 0: unlimited)")
      ->capture_default_str();
  command.add_option("--host-out-bytes-per-cycle", config.hostOutput.bytesPerCycle,
                     "host output link rate (0: unlimited)")
      ->capture_default_str();
  command.add_option("--clock-mhz", config.clockMhz, "clock for rates and frame rates")
      ->capture_default_str();
  command.add_flag("--allow-stack-overflow", options.allowStackOverflow,
                   "run even when a tree is deeper than the stack (such rays are flagged)");
  command.add_option("--stats", options.statsPath, "write the statistics as JSON");
  CLI::Option* vcd = command.add_option("--vcd", options.vcdPath, "write a VCD trace (GTKWave)");
  command.add_option("--vcd-from", options.vcdFrom, "first traced cycle")->needs(vcd);
  command.add_option("--vcd-to", options.vcdTo, "cycle the trace stops before")->needs(vcd);
  command.add_option("--vcd-scope", options.vcdScopes,
                     "trace only these modules, e.g. rtu.core_3 rtu.scheduler (default: all)")
      ->needs(vcd);
}

RtuConfig RtuOptions::resolve(const GoldenConfig& golden) const {
  RtuConfig resolved = config;
  resolved.memory.ideal = memory == "ideal";
  resolved.jobManager.format = golden.format;
  resolved.jobManager.conversion = golden.conversion;
  resolved.stackFrames = golden.stackFrames;
  if (!vcdPath.empty()) resolved.trace = TraceOptions{vcdPath, vcdFrom, vcdTo, vcdScopes};
  return resolved;
}

void reportRun(const RtuRun& run, const RtuOptions& options, std::ostream& out) {
  run.statistics.writeReport(out);
  if (options.statsPath.empty()) return;
  std::ofstream file(options.statsPath);
  file << run.statistics.toJson().dump(2) << "\n";
  if (!file) throw std::runtime_error("cannot write statistics file " + options.statsPath);
  out << "wrote       " << options.statsPath << "\n";
}

}  // namespace rtu
