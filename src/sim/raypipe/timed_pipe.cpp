// The timed model of seed 001's ray pipe (raypipe_timed.h): the run and the cycle's order of unit
// groups (timed_pipe.h).
#include "sim/raypipe/timed_pipe.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/raypipe/raypipe_timed.h"

namespace rtu {
namespace raypipe_timed {
namespace {

// The furthest a cache's wake lies ahead: a line's doneRead, its grant at most a turn of the
// arbiter's ports away.
int64_t dramHorizon(const RaypipeConfig& c) {
  if (c.cache != RaypipeCacheKind::SetAssociative) return 0;
  return kRaypipeDramPorts + c.caches.dramLatency +
         static_cast<int64_t>(std::ceil(48 / c.caches.dramBytesPerCycle));
}

}  // namespace

TimedPipe::TimedPipe(const RaypipeConfig& config, const KdImage& image,
                     const std::vector<RaypipeCycleRay>& rays, const RaypipeCycleOptions& options,
                     CycleTrace* trace)
    : config_(config),
      recordTransfers_(options.recordTransfers),
      cyclesSinceReset_(options.cyclesSinceReset),
      memory_(image.memory()),
      sections_(sectionsOf(decodeKdHeader(image.words.data()))),
      rays_(rays),
      c_(config),
      calendar_(8 +
                std::max({config.latency.prg, config.latency.prgInterval, config.latency.sint,
                          config.latency.sintInterval, config.latency.travMath,
                          config.latency.intersection, config.latency.memoryRead, 4}) +
                dramHorizon(config)),
      records_(static_cast<size_t>(config.raysInFlight)),
      stack_(static_cast<size_t>(config.raysInFlight * config.shortStackDepth)),
      results_(rays.size()),
      busy_(static_cast<size_t>(Unit::kCount), 0),
      stall_(static_cast<size_t>(Unit::kCount), 0) {
  for (size_t i = 0; i < rays.size(); ++i) results_[i].pixelId = rays[i].pixelId;
  if (trace) traceTo(*trace);
  vgaReadWindow_ = options.writer.vgaReadWindow;
  vga_ = VgaWindow(options.writer.vgaPhase);
  // The shader's reset fill (is_init): ray id i written i cycles after reset, results blocked for
  // the fill's 512 cycles.
  const int64_t reset = -std::min<int64_t>(options.cyclesSinceReset, 1000000);
  for (int id = 0; id < config.raysInFlight; ++id)
    c_.idFifo.preload(static_cast<uint32_t>(id), reset + id);
  initEnd_ = reset + 512;
  c_.dram.startAfter(options.cyclesSinceReset);
  wireCalendar();
  calendar_.book(kPrg, 0, -1);
}

void TimedPipe::traceTo(CycleTrace& trace) {
  trace_ = std::make_unique<PipeTrace>(trace, config_, rays_.size());
  for (Fifo* f : c_.fifos()) f->traceTo(&trace_->fifo(f->name(), f->depth(), f == &c_.prgFifo));
  c_.idFifo.traceTo(&trace_->fifo(c_.idFifo.name(), c_.idFifo.depth()));
  trace.checkScopesMatched();  // a scope that matches none of the pipe's, before any cycle
}

// Which groups act on which channel: the one that reads it and the one whose code pops it when
// an arbiter takes its head, the one that takes a pipe's items out, the ones reading a register.
// The PRG's FIFO and the ray ids book nobody: the PRG and SINT's issue side run on v0 and v2.
void TimedPipe::wireCalendar() {
  WakeCalendar& k = calendar_;
  c_.prgPipe.bookOn(k, kPrg);
  c_.sintPipe.bookOn(k, kSint);
  c_.sintTarb.bookOn(k, kSint | kTrav);
  c_.sintSs.bookOn(k, kSint | kStack);
  c_.sintShader.bookOn(k, kSint | kShader);
  for (size_t i = 0; i < c_.trav.size(); ++i) {
    TravUnit& u = c_.trav[i];
    c_.tarb.out(static_cast<int>(i)).bookOn(k, kTrav);
    u.tcache.bookOn(k, kTrav);
    for (Fifo* f : {&u.rs0.fifo, &u.leafFifo, &u.travFifo}) f->bookOn(k, kTrav);
    for (auto* p : {&u.rs0.pipe, &u.travPipe}) p->bookOn(k, kTrav);
    u.travTarb.bookOn(k, kTrav);
    u.travList.bookOn(k, kTrav);
    u.travSs.bookOn(k, kTrav | kStack);
    u.travLarb.bookOn(k, kTrav | kInt);
    c_.stackWrite[i].bookOn(k, kStack);
  }
  for (size_t i = 0; i < 3; ++i)
    for (Fifo* f : {&c_.stackRead[i], &c_.restRead[i], &c_.restWrite[i]}) f->bookOn(k, kStack);
  c_.stackPipe.bookOn(k, kStack);
  c_.restPipe.bookOn(k, kStack);
  c_.stackFifo.bookOn(k, kStack | kTrav);
  c_.notMissFifo.bookOn(k, kStack | kTrav);
  c_.missFifo.bookOn(k, kStack | kShader);
  c_.lcache.bookOn(k, kInt);
  c_.icache.bookOn(k, kInt);
  for (Fifo* f : {&c_.larb.out(), &c_.rs1.fifo, &c_.intLarb}) f->bookOn(k, kInt);
  for (auto* p : {&c_.rs1.pipe, &c_.intPipe}) p->bookOn(k, kInt);
  c_.intList.bookOn(k, kInt | kList);
  c_.listLast.bookOn(k, kList);
  c_.listHitFifo.bookOn(k, kList);
  for (auto* p : {&c_.listPipe, &c_.listHitPipe, &c_.rs2.pipe}) p->bookOn(k, kList);
  c_.toSs.bookOn(k, kList | kStack);
  c_.rs2.fifo.bookOn(k, kList | kShader);
  for (Fifo* f : {&c_.shaderArb.out(), &c_.shaderData, &c_.pixelBuffer}) f->bookOn(k, kShader);
  c_.shaderPipe.bookOn(k, kShader);
}

// After `group` acted in now_ (its channels booked their groups as they were used): an arbiter
// holding an item books its group for the next cycle; the PRG and the shader's issue side book
// their next v0 while pixels are left and their next v2 while the PRG's FIFO holds a ray (the
// cycles between change nothing but SINT's stall count, which shaderIssueAndPrg adds up).
void TimedPipe::settle(uint32_t group) {
  const bool holds = (group == kTrav && c_.tarb.holds()) || (group == kInt && c_.larb.holds()) ||
                     (group == kShader && c_.shaderArb.holds());
  if (holds) calendar_.book(group, now_ + 1, now_);
  if (group != kPrg) return;
  if (issued_ < rays_.size()) {
    // Blocked: its FIFO full with its head shown and its pipe empty, the PRG stalls on every v0
    // until a v2 call (booked below) reads the FIFO; shaderIssueAndPrg adds those stalls up.
    prgBlocked_ =
        !c_.prgPipe.any() && c_.prgFifo.full(now_ + 1) && c_.prgFifo.headShownFrom() <= now_ + 1;
    const int64_t interval = config_.latency.prgInterval;
    if (!prgBlocked_) calendar_.book(kPrg, (now_ / interval + 1) * interval, now_);
  }
  if (c_.prgFifo.any()) {
    const int64_t interval = config_.latency.sintInterval;
    const int64_t from = std::max(now_ + 1, c_.prgFifo.headShownFrom());
    calendar_.book(kPrg, (from + 1 + interval - 1) / interval * interval - 1, now_);
  }
}

void TimedPipe::busy(Unit u, const RayToken& t, bool hasRay) {
  ++busy_[static_cast<size_t>(u)];
  lastProgress_ = now_;
  if (recordTransfers_ || trace_) recordTransfer(u, t, hasRay);
}

// Out of busy()'s path (cold, not inlined): a run that neither traces nor records transfers pays
// one test per transfer.
void TimedPipe::recordTransfer(Unit u, const RayToken& t, bool hasRay) {
  if (trace_) trace_->took(u, now_, hasRay ? t.ray : t.index);
  if (recordTransfers_)
    transfers_.push_back(
        RaypipeTransfer{now_, unitName(u), hasRay ? t.ray : RaypipeTransfer::kNoRayId, t.index});
}

void TimedPipe::step() {
  // every register read once (a valid one books its readers for the next cycle)
  for (size_t i = 0; i < c_.trav.size(); ++i) {
    TravUnit& u = c_.trav[i];
    u.travTarb.valid(now_);
    u.travLarb.valid(now_);
    u.travList.valid(now_);
    travToSsStall_[i] = travToSsStall(i);
  }
  listToSsStall_ = listToSsStall();
  sintToSsStall_ = c_.sintSs.shown(now_) && c_.restWrite[2].full(now_);
  listToRsStall_ = intToListStall_ = sintUsStall_ = false;  // a group not called: low
  const std::pair<uint32_t, void (TimedPipe::*)()> groups[] = {
      {kShader, &TimedPipe::shaderReturn},  {kList, &TimedPipe::listUnit},
      {kInt, &TimedPipe::intersection},     {kTrav, &TimedPipe::traversal},
      {kStack, &TimedPipe::shortStack},     {kSint, &TimedPipe::sceneIntersection},
      {kPrg, &TimedPipe::shaderIssueAndPrg}};
  for (const auto& g : groups) {
    if (!runs(g.first)) continue;
    (this->*g.second)();
    settle(g.first);
  }
}

RaypipeCycleRun TimedPipe::run() {
  const auto start = std::chrono::steady_clock::now();
  const int64_t flushCycles = static_cast<int64_t>(TraceOptions{}.flushCycles);
  while (written_ < rays_.size()) {
    booked_ = calendar_.take(now_);
    if (booked_) step();
    if (trace_ && now_ % flushCycles == 0) trace_->flush(safeCycle());
    if (now_ - lastProgress_ > 1000000)
      throw std::logic_error("raypipe timed model: no progress for a million cycles at cycle " +
                             std::to_string(now_));
    ++now_;
  }
  RaypipeCycleRun run;
  run.setResults(results_);
  if (trace_) {
    int64_t firstExit = run.lastExitCycle;
    for (const RaypipeCycleResult& r : results_) firstExit = std::min(firstExit, r.exitCycle);
    trace_->finish(std::max<int64_t>(firstExit, 0));
  }
  run.lastWriteCycle = lastWrite_;
  run.writerWaits = writerWaits_;
  run.transfers = std::move(transfers_);
  for (size_t i = 0; i < static_cast<size_t>(Unit::kCount); ++i)
    run.units.push_back(RaypipeUnitActivity{unitName(static_cast<Unit>(i)), busy_[i], stall_[i]});
  run.fifos = c_.peaks();
  run.maxRaysInFlight = maxInFlight_;
  run.staleListHits = staleListHits_;
  if (config_.cache == RaypipeCacheKind::SetAssociative) {
    run.caches = c_.cacheCounts();
    run.dram = c_.dram.counts();
  }
  run.hostSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace raypipe_timed

void checkRaypipeTimedTakes(const RaypipeConfig& config) { config.validate(); }

RaypipeCycleRun runRaypipeTimed(const RaypipeConfig& config, const KdImage& image,
                                const std::vector<RaypipeCycleRay>& rays,
                                const RaypipeCycleOptions& options, CycleTrace* trace) {
  checkRaypipeTimedTakes(config);
  if (options.writer.vgaPhase < 0)
    throw std::invalid_argument("the VGA phase must not be negative");
  if (options.cyclesSinceReset < 0)
    throw std::invalid_argument("the cycles since reset must not be negative");
  raypipe_timed::TimedPipe pipe(config, image, rays, options, trace);
  return pipe.run();
}

}  // namespace rtu
