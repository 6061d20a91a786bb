#include "sim/lt/lt_top.h"

#include <stdexcept>
#include <string>

namespace rtu {

LtTopBase::LtTopBase(sc_core::sc_module_name name, const RtuConfig& config, WordMemory memory,
                     RecordSource records, LtArrival arrived, uint32_t accessBytes)
    : sc_core::sc_module(name),
      config_(config),
      records_(std::move(records)),
      arrived_(std::move(arrived)),
      memory_(memory),
      accessBytes_(accessBytes),
      time_(CycleClock::atMegahertz(config.clockMhz)),
      setup_(makeCoreJobSetup(config.core, memory, config.jobManager, config.coreConfigs)) {
  tlm_utils::tlm_quantumkeeper::set_global_quantum(time_.period() *
                                                   static_cast<double>(config.ltQuantum));
  stalls_.assign(static_cast<size_t>(config.cores), 0);
  if (config.trianglesShared()) {
    const uint32_t interval = withCoreKind(config.core, [&config](auto kind) {
      return triangleIntervalOf<decltype(kind)>(config.coreConfig<decltype(kind)>());
    });
    units_.resize(static_cast<size_t>((config.cores + config.triangleSharedBy - 1) /
                                      config.triangleSharedBy));
    for (LtTriangleUnit& unit : units_) unit.interval = interval;
  }
  if (config.memory.ideal) {
    rom_ = std::make_unique<LtRom>("rom", memory, accessBytes);
  } else {
    l2_ = std::make_unique<LtL2Cache>("l2", config.memory, time_);
    dram_ = std::make_unique<LtDram>("dram", config.memory.dram, config.memory.l2.lineBytes, time_);
    l2_->dram.bind(dram_->socket);
  }
  SC_HAS_PROCESS(LtTopBase);
  SC_THREAD(drive);
}

void LtTopBase::bindCore(tlm::tlm_initiator_socket<>& socket) {
  if (rom_) {
    socket.bind(rom_->socket);
    return;
  }
  l1_.push_back(std::make_unique<LtL1Cache>(("l1_" + std::to_string(l1_.size())).c_str(),
                                            config_.memory.l1, accessBytes_, memory_, time_));
  socket.bind(l1_.back()->socket);
  l1_.back()->next.bind(l2_->socket);
}

// The recurrence asks for each record in host order: the job manager sets it up then (model
// headers are read by the first ray against them), and the recurrence calls traverse() at its
// dispatch, before it asks for the next; each result goes to the host as the recurrence drains it.
void LtTopBase::drive() {
  quantum_.reset();
  totals_ = streamRecurrence(
      records_.size(), [this](size_t job) { return setUp(job); },
      RecurrenceConfig{config_.cores, config_.scheduler, config_.hostInput, config_.outputLink()},
      [this](const JobCycles& cycles) { drained(cycles); },
      [this](size_t job, int core, uint64_t initCycle) { return traverse(job, core, initCycle); });
}

JobTiming LtTopBase::setUp(size_t job) {
  const CoreKindJobSetUp set = setup_(records_[job]);
  current_ = CoreJob{PayloadIds::plain(job), set.idWord, set.job};
  return JobTiming{0, set.latency, set.headerFetch};
}

// Dispatches come in cycle order: the thread's local time is the latest, synchronised with the
// kernel once it runs a quantum ahead. They come in job order too, each right after its set-up.
uint64_t LtTopBase::traverse(size_t job, int core, uint64_t initCycle) {
  if (job != firstInFlight_ + inFlight_.size())
    throw std::logic_error("LtTop: jobs must be dispatched in order");
  quantum_.set(time_.delayTo(initCycle));
  if (quantum_.need_sync()) quantum_.sync();
  // Later jobs are dispatched no earlier: their tests come after this one's first state.
  if (LtTriangleUnit* unit = triangleUnitOf(core)) unit->issues.forgetBefore(initCycle);
  const LtTraversal traversal = traverseOn(core, current_, initCycle);
  inFlight_.back().blocked = traversal.blocked;
  stalls_[static_cast<size_t>(core)] += traversal.stalled;
  return traversal.cycles;
}

// Results drain out of job order: each is handed on at once, and the oldest are let go of once
// every one before them has drained.
void LtTopBase::drained(const JobCycles& cycles) {
  InFlight& job = inFlight_[cycles.job - firstInFlight_];
  arrived_(cycles, job.result, job.blocked);
  job.drained = true;
  for (; !inFlight_.empty() && inFlight_.front().drained; ++firstInFlight_) inFlight_.pop_front();
}

std::vector<CacheStats> LtTopBase::l1Statistics() const {
  std::vector<CacheStats> stats;
  for (const auto& l1 : l1_) stats.push_back(l1->statistics());
  return stats;
}

L2Stats LtTopBase::l2Statistics() const {
  if (!l2_) return {};
  L2Stats stats = l2_->statistics();
  stats.dram = dram_->statistics();
  return stats;
}

}  // namespace rtu
