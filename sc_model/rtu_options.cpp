#include "rtu_options.h"

#include <fstream>
#include <ostream>
#include <stdexcept>

#include "cli_options.h"
#include "timing_limits.h"

namespace rtu {

RtuConfig RunOutputs::traced(const RtuConfig& config) const {
  RtuConfig resolved = config;
  if (!vcdPath.empty()) resolved.trace = TraceOptions{vcdPath, vcdFrom, vcdTo, vcdScopes};
  return resolved;
}

void addRunOutputOptions(CLI::App& command, RunOutputs& outputs) {
  command.add_option("--stats", outputs.statsPath,
                     "write the statistics with the effective configuration as JSON");
  CLI::Option* vcd = command.add_option("--trace,--vcd", outputs.vcdPath,
                                        "write a trace for GTKWave: FST for a .fst path, else VCD");
  const CLI::Range cycles(uint64_t{0}, kMaxCycles, "cycle in 0 .. 1e13");
  command.add_option("--vcd-from", outputs.vcdFrom, "first traced cycle")
      ->needs(vcd)
      ->check(kNotNegative)
      ->check(cycles);
  command.add_option("--vcd-to", outputs.vcdTo, "cycle the trace stops before")
      ->needs(vcd)
      ->check(kNotNegative)
      ->check(cycles);
  command.add_option("--trace-scope,--vcd-scope", outputs.vcdScopes,
                     "trace only these modules, e.g. rtu.core_3 rtu.scheduler (default: all)")
      ->needs(vcd);
}

nlohmann::ordered_json runJson(const RtuStatistics& statistics, const Configuration& configuration) {
  return {{"rtusim", {{"version", rtusimVersion()}}},
          {"config", configuration.toJson()},
          {"statistics", statistics.toJson()}};
}

void reportRun(const RtuRun& run, const Configuration& configuration, const RunOutputs& outputs,
               std::ostream& out) {
  run.statistics.writeReport(out);
  if (outputs.statsPath.empty()) return;
  std::ofstream file(outputs.statsPath);
  file << runJson(run.statistics, configuration).dump(2) << "\n";
  if (!file) throw std::runtime_error("cannot write statistics file " + outputs.statsPath);
  out << "wrote       " << outputs.statsPath << "\n";
}

}  // namespace rtu
