#include "sim/ca/memory_system.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rtu {

MemorySystem::MemorySystem(sc_core::sc_module_name name, const CycleClock& clock,
                           DecisionPump& pump, WordMemory backing, MemoryConfig config, int cores,
                           uint64_t firstReadAfterDispatch, TriangleUnitArbiter units,
                           CycleTrace* trace, const CacheContents* start)
    : sc_core::sc_module(name),
      Agent(pump),
      clock_(clock),
      backing_(backing),
      config_(config),
      cores_(static_cast<size_t>(cores)),
      calendar_(static_cast<size_t>(cores), kNoBound),
      units_(std::move(units)),
      firstRead_(firstReadAfterDispatch),
      published_(static_cast<size_t>(cores), firstRead_),  // ready from cycle 0
      wake_(clock),
      trace_(trace) {
  while ((1 << coreBits_) < cores) ++coreBits_;
  if (config_.ideal) return;
  validate(config_);
  l2_ = std::make_unique<L2CacheTiming>(config_.l2, config_.dram);
  if (start && !start->l2.empty()) l2_->startFrom(start->l2.front());
  for (size_t i = 0; i < cores_.size(); ++i) {
    CorePort& port = cores_[i];
    port.l1 = std::make_unique<L1CacheTiming>(config_.l1);
    if (start && i < start->l1.size()) port.l1->startFrom(start->l1[i]);
    if (trace_) {
      const std::string scope = std::string(this->name()) + ".l1_" + std::to_string(i);
      port.hitSignal = trace_->declare(scope, "hits", 32);
      port.missSignal = trace_->declare(scope, "misses", 32);
    }
  }
  if (trace_) {
    const std::string scope = std::string(this->name()) + ".l2";
    l2HitSignal_ = trace_->declare(scope, "hits", 32);
    l2MissSignal_ = trace_->declare(scope, "misses", 32);
  }
}

void MemorySystem::followDispatches(DispatchFloor& scheduler) {
  if (!serves()) return;
  dispatches_ = &scheduler;
  scheduler.watchDispatchFloor(*this);
}

void MemorySystem::end_of_elaboration() {
  if (!serves()) return;
  spawnReaction("serve_shared", [this] { pump().runWith(*this); }, {&wake_.event()});
}

void MemorySystem::tracePrivateLookup(int core, uint64_t cycle) {
  if (!trace_) return;
  const CorePort& port = cores_[static_cast<size_t>(core)];
  trace_->record(port.hitSignal, cycle, port.l1->stats().hits + port.l1->stats().merged);
  trace_->record(port.missSignal, cycle, port.l1->stats().misses);
}

void MemorySystem::requestShared(int core, uint32_t address, uint64_t cycle,
                                 SharedReadListener& reader) {
  cores_[static_cast<size_t>(core)].pendingAddress = address;
  cores_[static_cast<size_t>(core)].unit = false;
  enterCalendar(core, cycle, reader);
}

void MemorySystem::requestTriangleUnit(int core, uint64_t cycle, SharedReadListener& reader) {
  cores_[static_cast<size_t>(core)].unit = true;
  enterCalendar(core, cycle, reader);
}

void MemorySystem::enterCalendar(int core, uint64_t cycle, SharedReadListener& reader) {
  if (cycle <= std::max(clock_.now(), servedThrough_)) failBehind(core, cycle);
  CorePort& port = cores_[static_cast<size_t>(core)];
  port.reader = &reader;
  // A core publishes no bound while it runs: its first request after its offer drops it.
  if (published_.value(static_cast<size_t>(core)) != kNoBound)
    published_.set(static_cast<size_t>(core), kNoBound);
  calendar_.set(static_cast<size_t>(core), requestKey(cycle, core));
  heard(0);
}

void MemorySystem::failBehind(int core, uint64_t cycle) const {
  throw std::logic_error("shared request of core " + std::to_string(core) + " for cycle " +
                         std::to_string(cycle) +
                         ", not after simulated time and the cycles served");
}

// Handed over in outCycle at the earliest, then idle and dispatched from the cycle after: its
// first read follows firstRead_ cycles later. The bound holds until the dispatch, however long
// it waits.
void MemorySystem::coreOffering(int core, uint64_t outCycle) {
  published_.set(static_cast<size_t>(core), outCycle + 1 + firstRead_);
  heard(0);
}

// Decides after every other agent, so that each core's and the scheduler's bounds are settled;
// only while a request waits.
void MemorySystem::heard(int) {
  if (requestsWait()) pump().scheduleLast(*this);
}

// It goes on serving while the replies queue other agents: a reply makes a core run and perhaps
// offer, which queues the result manager or the scheduler, but no job is dispatched until the
// scheduler decides, so every bound still holds.
void MemorySystem::decide() {
  while (requestsWait()) {
    const uint64_t cycle = earliestRequestCycle();
    if (!requestsKnownFor(cycle)) {
      // What the replies woke may raise the bounds: decide again after it, without a kernel event.
      if (pump().othersQueued()) {
        heard(0);
        return;
      }
      wake_.at(cycle);  // by then they are: every decision about a cycle is made by its time
      return;
    }
    serveCycle(cycle);
  }
}

// (A cycle simulated time has reached is below the floor's + firstRead_.)
bool MemorySystem::requestsKnownFor(uint64_t cycle) const {
  return cycle < std::max(published_.lowest(), dispatchFloor() + firstRead_);
}

void MemorySystem::servedLast(int core) {
  nextPriority_ = core + 1 == static_cast<int>(cores_.size()) ? 0 : core + 1;
}

// The earliest cycle the scheduler can still dispatch a job in.
uint64_t MemorySystem::dispatchFloor() const {
  const uint64_t now = clock_.now();
  return dispatches_ ? std::max(now, dispatches_->noDispatchBefore()) : now;
}

void MemorySystem::serveCycle(uint64_t cycle) {
  servedThrough_ = cycle;
  const int first = takeEarliest();
  if ((requestsWait() && earliestRequestCycle() == cycle) ||
      cores_[static_cast<size_t>(first)].unit) {
    serveArbitrated(first, cycle);
    return;
  }
  servedLast(first);  // the only request of its cycle, as most are: nothing to arbitrate
  serve(first, cycle);
  if (trace_) traceShared(cycle);
}

// The requests of one cycle: `first` and those left in the calendar for it, the shared level's
// round-robin from the core after the one served last on (a core has one request at most), and
// the triangle units' requests apart.
void MemorySystem::serveArbitrated(int first, uint64_t cycle) {
  served_.clear();
  unitRequests_.clear();
  for (int core = first;;) {  // in increasing core numbers
    (cores_[static_cast<size_t>(core)].unit ? unitRequests_ : served_).push_back(core);
    if (!requestsWait() || earliestRequestCycle() != cycle) break;
    core = takeEarliest();
  }
  if (!unitRequests_.empty()) serveUnits(cycle);
  const size_t count = served_.size();
  if (count == 0) return;
  size_t start = 0;  // the first at or after the core whose turn it is
  while (start < count && served_[start] < nextPriority_) ++start;
  servedLast(served_[start == 0 ? count - 1 : start - 1]);  // the last in this cycle's turn
  for (size_t i = start; i < count; ++i) serve(served_[i], cycle);
  for (size_t i = 0; i < start; ++i) serve(served_[i], cycle);
  if (trace_) traceShared(cycle);
}

// The waiting requests go back into the calendar before a granted core goes on (and perhaps asks
// again, for a later cycle).
void MemorySystem::serveUnits(uint64_t cycle) {
  units_.arbitrate(cycle, unitRequests_, unitsGranted_, unitsDeferred_);
  for (const auto& [core, next] : unitsDeferred_) {
    calendar_.set(static_cast<size_t>(core), requestKey(next, core));
    cores_[static_cast<size_t>(core)].reader->unitDeferred(next);
  }
  for (int core : unitsGranted_) {
    CorePort& port = cores_[static_cast<size_t>(core)];
    SharedReadListener& reader = *port.reader;
    port.reader = nullptr;
    reader.unitGranted(cycle);
  }
}

void MemorySystem::traceShared(uint64_t cycle) {
  const L2Stats stats = l2_->stats();
  trace_->record(l2HitSignal_, cycle, stats.cache.hits + stats.cache.merged);
  trace_->record(l2MissSignal_, cycle, stats.cache.misses);
}

// The core of the earliest request in the calendar, which it leaves.
int MemorySystem::takeEarliest() {
  const int core = coreOf(calendar_.lowest());
  calendar_.set(static_cast<size_t>(core), kNoBound);
  return core;
}

void MemorySystem::serve(int core, uint64_t cycle) {
  CorePort& port = cores_[static_cast<size_t>(core)];
  const uint64_t line = L1CacheTiming::byteAddress(port.pendingAddress);
  SharedReadListener& reader = *port.reader;
  port.reader = nullptr;
  // The core goes on at once, and either asks again (for a later cycle) or publishes a bound.
  reader.sharedReplied(port.l1->fill(port.pendingAddress, l2_->read(line, cycle)));
}

}  // namespace rtu
