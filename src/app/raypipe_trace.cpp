#include "app/raypipe_trace.h"

#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>

#include "explore/raypipe_frame.h"
#include "run/trace_plan.h"
#include "trace/cycle_trace.h"
#include "trace/gtkw_save_file.h"
#include "trace/raypipe_timeline.h"

namespace rtu {
namespace {

// The trace and timeline asked for, with --trace-ray's window.
struct PipeTraceFiles {
  TraceOptions trace;
  TimelineOptions timeline;
};

PipeTraceFiles plannedFiles(const RaypipeConfig& config, const RaypipeCycleRun& run,
                            const RunOutputs& outputs, std::ostream& out) {
  const uint64_t periodPs = static_cast<uint64_t>(std::llround(1e6 / config.clockMHz));
  PipeTraceFiles files{outputs.traceOptions(periodPs),
                       TimelineOptions{outputs.timelinePath, outputs.vcdFrom, outputs.vcdTo}};
  if (outputs.traceRay < 0) return files;
  const uint64_t ray = static_cast<uint64_t>(outputs.traceRay);
  if (ray >= run.results.size())
    throw std::invalid_argument("--trace-ray " + std::to_string(ray) + ": the frame has " +
                                std::to_string(run.results.size()) + " rays (0 to " +
                                std::to_string(run.results.size() - 1) + ", in issue order)");
  const RaypipeCycleResult& r = run.results[ray];
  out << "window      ray " << ray << " (pixel " << r.pixelId << ", ray id " << r.rayId
      << "): cycles " << r.issueCycle << " to " << r.exitCycle << "\n";
  files.trace.fromCycle = files.timeline.fromCycle = static_cast<uint64_t>(r.issueCycle);
  files.trace.toCycle = files.timeline.toCycle = static_cast<uint64_t>(r.exitCycle) + 1;
  files.trace.markerCycle = static_cast<uint64_t>(r.exitCycle);
  return files;
}

// The trace's VCD bytes, from a run that writes nothing.
uint64_t countedTraceBytes(const RaypipeConfig& config, const std::vector<uint32_t>& image,
                           const std::vector<PrimaryRay>& rays, TraceOptions trace) {
  trace.countOnly = true;
  CycleTrace counter(trace);
  runRaypipeFrame(config, image, rays, &counter);
  return counter.countedBytes();
}

}  // namespace

void writeRaypipeTraces(const RaypipeConfig& config, const std::vector<uint32_t>& image,
                        const std::vector<PrimaryRay>& rays, const RaypipeCycleRun& run,
                        const RunOutputs& outputs, std::ostream& out) {
  const bool traced = !outputs.vcdPath.empty(), timeline = !outputs.timelinePath.empty();
  if (!traced && !timeline) {
    if (!outputs.needingOutput.empty())
      throw std::invalid_argument(outputs.needingOutput + " needs --trace or --timeline");
    return;
  }
  PipeTraceFiles files = plannedFiles(config, run, outputs, out);
  const uint64_t periodPs = files.trace.periodPs;
  TraceSizes sizes;
  if (traced) {
    sizes.vcd = countedTraceBytes(config, image, rays, files.trace);
    sizes.trace = traceFileBytes(outputs.vcdPath, sizes.vcd);
  }
  if (timeline) {
    TimelineOptions counting = files.timeline;
    counting.countOnly = true;
    sizes.timeline = writeRaypipeTimeline(run, counting, periodPs, config.raysInFlight);
  }
  reportTraceSizes(sizes, outputs.vcdPath, outputs.timelinePath,
                   {outputs.traceRay, outputs.traceMaxMb * 1000000}, out);
  if (traced) {
    CycleTrace trace(files.trace);
    runRaypipeFrame(config, image, rays, &trace);
    out << "wrote       " << outputs.vcdPath << " (and " << saveFilePath(outputs.vcdPath) << ")\n";
  }
  if (timeline) {
    writeRaypipeTimeline(run, files.timeline, periodPs, config.raysInFlight);
    out << "wrote       " << outputs.timelinePath << "\n";
  }
}

}  // namespace rtu
