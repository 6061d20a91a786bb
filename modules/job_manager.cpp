#include "job_manager.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rtu {

JobManager::JobManager(sc_core::sc_module_name name, const CycleClock& clock,
                       JobManagerConfig config, SvoMemory memory)
    : sc_core::sc_module(name), clock_(clock), config_(config), setup_(memory, config), wake_(clock) {
  if (config_.stages < 1 || config_.stages > 64 || config_.rayStages < 0 || config_.rayStages > 64)
    throw std::invalid_argument("job manager pipeline must have 1 to 64 stages (0 to 64 more for "
                                "rays), got " + std::to_string(config_.stages) + " and " +
                                std::to_string(config_.rayStages));
  if (config_.headerFetchCycles < 0)
    throw std::invalid_argument("model header fetch cycles must not be negative");
  config_.format.validate();
}

void JobManager::end_of_elaboration() {
  spawnMethod("evaluate", [this] { evaluate(); },
              {&in->edge(), &out->edge(), &out->readyChanged(), &wake_.event()});
}

bool JobManager::outputValid(uint64_t now) const {
  return !pipeline_.empty() && pipeline_.front().outputCycle <= now;
}

void JobManager::evaluate() {
  const uint64_t now = clock_.now();
  takeTransfers(now);
  const bool valid = outputValid(now);
  if (valid && !offering_) {
    pipeline_.front().job.pendingSince = now;
    out->offer(pipeline_.front().job);
    offering_ = true;
  }
  in->setReady((!valid || out->ready()) && now >= fetchUntil_);  // pipeline_enable
  uint64_t wake = now >= fetchUntil_ ? ~0ull : fetchUntil_;
  if (!valid && !pipeline_.empty()) wake = std::min(wake, pipeline_.front().outputCycle);
  if (wake != ~0ull) wake_.at(wake);
}

// The edge that ended the previous cycle, handled once however often the cycle wakes us.
void JobManager::takeTransfers(uint64_t now) {
  if (handledCycle_ == now || now == 0) return;
  handledCycle_ = now;
  const uint64_t edge = now - 1;
  if (out->transferredIn(edge)) {
    const uint64_t stall = edge - pipeline_.front().outputCycle;
    statistics_.stallCycles += stall;
    pipeline_.pop_front();
    for (InFlight& job : pipeline_) job.outputCycle += stall;
    out->withdraw();  // replaced by the next offer if a job reaches the output now
    offering_ = false;
  }
  if (in->transferredIn(edge)) accept(in->transferred(), edge);
}

void JobManager::accept(const HostJob& host, uint64_t edge) {
  const JobSetup::SetUp set = setup_.setUp(host.record);
  if (set.headerFetch > 0) fetchUntil_ = edge + 1 + set.headerFetch;
  uint64_t outputCycle = edge + set.latency;
  if (!pipeline_.empty()) outputCycle = std::max(outputCycle, pipeline_.back().outputCycle + 1);
  pipeline_.push_back(InFlight{convert(host.sequence, set.job), outputCycle});
}

CoreJob JobManager::convert(uint64_t sequence, const TraversalJob& host) const {
  CoreJob job;
  job.sequence = sequence;
  job.idWord = host.idWord();
  job.a = host.a;
  job.t0 = convertToFixed(host.t0Bits, config_.format, config_.conversion);
  job.t1 = convertToFixed(host.t1Bits, config_.format, config_.conversion);
  job.root = host.root;
  return job;
}

}  // namespace rtu
