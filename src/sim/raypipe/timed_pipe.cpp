// The timed model of seed 001's ray pipe (raypipe_timed.h): the run and the cycle's order of unit
// groups (timed_pipe.h).
#include "sim/raypipe/timed_pipe.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "sim/raypipe/raypipe_timed.h"

namespace rtu {
namespace raypipe_timed {

TimedPipe::TimedPipe(const RaypipeConfig& config, const KdImage& image,
                     const std::vector<RaypipeCycleRay>& rays, const RaypipeCycleOptions& options)
    : config_(config),
      recordTransfers_(options.recordTransfers),
      memory_(image.memory()),
      sections_(sectionsOf(decodeKdHeader(image.words.data()))),
      rays_(rays),
      c_(config),
      records_(static_cast<size_t>(config.raysInFlight)),
      stack_(static_cast<size_t>(config.raysInFlight * config.shortStackDepth)),
      results_(rays.size()),
      busy_(static_cast<size_t>(Unit::kCount), 0),
      stall_(static_cast<size_t>(Unit::kCount), 0) {
  for (size_t i = 0; i < rays.size(); ++i) results_[i].pixelId = rays[i].pixelId;
  // The shader's reset fill (is_init): ray id i written i cycles after reset, results blocked for
  // the fill's 512 cycles.
  const int64_t reset = -std::min<int64_t>(options.cyclesSinceReset, 1000000);
  for (int id = 0; id < config.raysInFlight; ++id)
    c_.idFifo.preload(static_cast<uint32_t>(id), reset + id);
  initEnd_ = reset + 512;
}

void TimedPipe::busy(Unit u, const RayToken& t, bool hasRay) {
  ++busy_[static_cast<size_t>(u)];
  lastProgress_ = now_;
  if (recordTransfers_)
    transfers_.push_back(
        RaypipeTransfer{now_, unitName(u), hasRay ? t.ray : RaypipeTransfer::kNoRayId, t.index});
}

void TimedPipe::step() {
  travToSsStall_ = travToSsStall();
  listToSsStall_ = listToSsStall();
  sintToSsStall_ = c_.sintSs.shown(now_) && c_.restWrite[2].full(now_);
  shaderReturn();
  listUnit();
  intersection();
  traversal();
  shortStack();
  sceneIntersection();
  shaderIssueAndPrg();
}

RaypipeCycleRun TimedPipe::run() {
  const auto start = std::chrono::steady_clock::now();
  while (written_ < rays_.size()) {
    step();
    if (now_ - lastProgress_ > 1000000)
      throw std::logic_error("raypipe timed model: no progress for a million cycles at cycle " +
                             std::to_string(now_));
    ++now_;
  }
  RaypipeCycleRun run;
  run.results = results_;
  for (const auto& r : results_) run.lastExitCycle = std::max(run.lastExitCycle, r.exitCycle);
  run.frameCycles = run.lastExitCycle + 1;
  run.lastWriteCycle = lastWrite_;
  run.transfers = std::move(transfers_);
  for (size_t i = 0; i < static_cast<size_t>(Unit::kCount); ++i)
    run.units.push_back(RaypipeUnitActivity{unitName(static_cast<Unit>(i)), busy_[i], stall_[i]});
  run.fifos = c_.peaks();
  run.maxRaysInFlight = maxInFlight_;
  run.staleListHits = staleListHits_;
  run.hostSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace raypipe_timed

RaypipeCycleRun runRaypipeTimed(const RaypipeConfig& config, const KdImage& image,
                                const std::vector<RaypipeCycleRay>& rays,
                                const RaypipeCycleOptions& options) {
  config.validate();
  if (config.traversalUnits != 1)
    throw std::invalid_argument(
        "raypipe.traversal_units: the timed model models one traversal unit (t5.sv)");
  if (config.cache != RaypipeCacheKind::BlockRam)
    throw std::invalid_argument("raypipe.cache: the timed model models the block RAMs");
  if (options.writer.vgaReadWindow)
    throw std::invalid_argument("the timed model does not model the VGA reader's window");
  if (options.cyclesSinceReset < 0)
    throw std::invalid_argument("the cycles since reset must not be negative");
  raypipe_timed::TimedPipe pipe(config, image, rays, options);
  return pipe.run();
}

}  // namespace rtu
