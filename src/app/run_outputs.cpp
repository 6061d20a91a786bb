#include "app/run_outputs.h"

#include <ostream>
#include <stdexcept>

#include "app/placement_flags.h"
#include "base/output_file.h"
#include "base/timing_limits.h"
#include "explore/sweep_workers.h"
#include "run/trace_plan.h"

namespace rtu {

RtuConfig RunOutputs::traced(const RtuConfig& config) const {
  if (!needingOutput.empty() && vcdPath.empty() && timelinePath.empty())
    throw std::invalid_argument(needingOutput + " needs --trace or --timeline");
  RtuConfig resolved = config;
  // (the period is the run's: simulateRtu sets it from clock_mhz)
  if (!vcdPath.empty()) resolved.trace = traceOptions(TraceOptions{}.periodPs);
  resolved.timeline = TimelineOptions{timelinePath, vcdFrom, vcdTo};
  return resolved;
}

TraceOptions RunOutputs::traceOptions(uint64_t periodPs) const {
  TraceOptions options{vcdPath, vcdFrom, vcdTo, vcdScopes, signalClasses};
  options.periodPs = periodPs;
  options.clock = traceClock;
  options.time = traceTime == "cycles" ? TraceTime::Cycles
                 : traceTime == "ps"   ? TraceTime::Picoseconds
                                       : TraceTime::Auto;
  return options;
}

RtuConfig plannedTrace(const WordMemory& memory, const std::vector<HostRecord>& records,
                       const RtuConfig& config, const RunOutputs& outputs, std::ostream& out) {
  RunProgressLine progress("dry run", "rays");
  return planTrace(memory, records, config, {outputs.traceRay, outputs.traceMaxMb * 1000000}, out,
                   progress.callback());
}

void addRunOutputOptions(CLI::App& command, RunOutputs& outputs) {
  command.add_option("--stats", outputs.statsPath,
                     "write the statistics with the effective configuration as JSON");
  CLI::Option* vcd = command.add_option("--trace,--vcd", outputs.vcdPath,
                                        "write a trace for GTKWave: FST for a .fst path, else VCD");
  command.add_option("--timeline", outputs.timelinePath,
                     "write a per-core timeline of the rays as Chrome trace-event JSON (Perfetto)");
  const CLI::Range cycles(uint64_t{0}, kMaxCycles, "cycle in 0 .. 1e13");
  CLI::Option* from =
      command.add_option("--trace-from,--vcd-from", outputs.vcdFrom, "first traced cycle")
          ->check(kNotNegative)
          ->check(cycles);
  CLI::Option* to =
      command.add_option("--trace-to,--vcd-to", outputs.vcdTo, "cycle the trace stops before")
          ->check(kNotNegative)
          ->check(cycles);
  CLI::Option* ray = command
                         .add_option("--trace-ray", outputs.traceRay,
                                     "trace and timeline from this ray's entry into the RTU to its "
                                     "result reaching the host")
                         ->check(CLI::Range(int64_t{0}, int64_t{1} << 40))
                         ->excludes(from)
                         ->excludes(to);
  command
      .add_option("--trace-scope,--vcd-scope", outputs.vcdScopes,
                  "trace only these modules, e.g. rtu.core_3 rtu.scheduler (default: all)")
      ->needs(vcd);
  command
      .add_option("--trace-signals", outputs.signalClasses,
                  "trace only these signal classes: handshakes, ids, states, stack, caches, "
                  "fifos (the ray pipe's FIFO counts) (default: all)")
      ->delimiter(',')
      ->needs(vcd);
  command
      .add_flag("--trace-clock", outputs.traceClock,
                "trace a clock (rtu.clk, high in the first half of every cycle): two changes "
                "per cycle")
      ->needs(vcd);
  command
      .add_option("--trace-time", outputs.traceTime,
                  "the trace's time unit: cycles (GTKWave shows cycle numbers; the clock period "
                  "must be a power of ten picoseconds, as 10 ns at 100 MHz), ps, or auto (cycles "
                  "where they can be, ps with --trace-clock), default auto")
      ->check(CLI::IsMember({"auto", "cycles", "ps"}))
      ->needs(vcd);
  CLI::Option* maxMb = command
                           .add_option("--trace-max-mb", outputs.traceMaxMb,
                                       "refuse a trace or timeline larger than this (measured by a "
                                       "dry run first), default 300")
                           ->check(CLI::Range(uint64_t{1}, uint64_t{1} << 30));
  for (CLI::Option* option : {from, to, ray, maxMb})
    option->each(
        [&outputs, option](const std::string&) { outputs.needingOutput = option->get_name(); });
}

void reportRun(const RtuRun& run, const Configuration& configuration, const RunOutputs& outputs,
               std::ostream& out) {
  run.statistics.writeReport(out);
  if (outputs.statsPath.empty()) return;
  writeTextFile(outputs.statsPath, runJson(run.statistics, configuration).dump(2) + "\n");
  out << "wrote       " << outputs.statsPath << "\n";
}

void checkOutputsOfModel(const RunOutputs& outputs, ModelKind model) {
  if (model == ModelKind::CycleAccurate) return;
  if (!outputs.vcdPath.empty() || !outputs.timelinePath.empty())
    throw std::invalid_argument(std::string("--trace and --timeline need --model ca: waveforms and "
                                            "timelines are the cycle-accurate model's, not ") +
                                toString(model) + "'s");
}

}  // namespace rtu
