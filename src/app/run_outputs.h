#pragma once
// What the commands that run the SystemC model write besides their main output: the --stats JSON
// (statistics with the whole effective configuration and the rtusim version) and the VCD trace.

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "app/output_paths.h"
#include "config/configuration.h"
#include "config/run_json.h"
#include "run/model_run.h"
#include "run/rtu_simulation.h"
#include "sim/rtu_config.h"

namespace rtu {

struct RunOutputs {
  std::string statsPath;
  std::string vcdPath;
  uint64_t vcdFrom = 0;
  uint64_t vcdTo = std::numeric_limits<uint64_t>::max();
  std::vector<std::string> vcdScopes;
  std::vector<std::string> signalClasses;
  bool traceClock = false;
  std::string traceTime = "auto";  // --trace-time: auto, cycles or ps (TraceTime)
  std::string timelinePath;
  int64_t traceRay = -1;  // -1: no --trace-ray
  uint64_t traceMaxMb = 300;
  std::string needingOutput;  // an option given that needs --trace or --timeline

  // The model configuration with the trace and the timeline asked for.
  RtuConfig traced(const RtuConfig& config) const;
  // The trace asked for (--trace and the options that shape it), at a clock of `periodPs`.
  TraceOptions traceOptions(uint64_t periodPs) const;
  std::vector<NamedPath> paths() const {
    return {{"--stats", statsPath}, {"--vcd", vcdPath}, {"--timeline", timelinePath}};
  }
  bool any() const { return !statsPath.empty() || !vcdPath.empty() || !timelinePath.empty(); }
};

void addRunOutputOptions(CLI::App& command, RunOutputs& outputs);
// Traces and timelines are the cycle-accurate model's: an error naming them for another model.
void checkOutputsOfModel(const RunOutputs& outputs, ModelKind model);

// `config` with the trace's window (--trace-ray), after measuring the trace and the timeline
// (src/run/trace_plan.h): prints their sizes, refuses one above --trace-max-mb.
RtuConfig plannedTrace(const WordMemory& memory, const std::vector<HostRecord>& records,
                       const RtuConfig& config, const RunOutputs& outputs, std::ostream& out);

// Prints the report and writes the --stats JSON if asked for.
void reportRun(const RtuRun& run, const Configuration& configuration, const RunOutputs& outputs,
               std::ostream& out);

}  // namespace rtu
