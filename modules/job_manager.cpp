#include "job_manager.h"

#include <stdexcept>
#include <string>

namespace rtu {

JobManager::JobManager(sc_core::sc_module_name name, const CycleClock& clock,
                       JobManagerConfig config)
    : sc_core::sc_module(name), clock_(clock), config_(config), wake_(clock) {
  if (config_.stages < 1 || config_.stages > 64)
    throw std::invalid_argument("job manager pipeline must have 1 to 64 stages, got " +
                                std::to_string(config_.stages));
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
  in->setReady(!valid || out->ready());  // pipeline_enable
  if (!valid && !pipeline_.empty()) wake_.at(pipeline_.front().outputCycle);
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
  if (in->transferredIn(edge)) {
    pipeline_.push_back(InFlight{convert(in->transferred()), edge + config_.stages});
    ++statistics_.jobs;
  }
}

CoreJob JobManager::convert(const HostJob& host) const {
  CoreJob job;
  job.sequence = host.sequence;
  job.idWord = host.job.idWord();
  job.a = host.job.a;
  job.t0 = convertToFixed(host.job.t0Bits, config_.format, config_.conversion);
  job.t1 = convertToFixed(host.job.t1Bits, config_.format, config_.conversion);
  job.root = host.job.root;
  return job;
}

}  // namespace rtu
