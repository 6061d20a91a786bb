#include "rtu_top.h"

#include <string>

namespace rtu {
namespace {

std::string indexed(const char* base, size_t index) { return base + std::to_string(index); }

template <class Payload>
void traceChannel(ReadyValid<Payload>& channel, CycleTrace* trace, const std::string& scope) {
  if (trace) channel.trace(*trace, scope);
}

}  // namespace

RtuTop::RtuTop(sc_core::sc_module_name name, const RtuConfig& config, SvoMemory memory,
               std::vector<HostRecord> records, CycleTrace* trace, const CacheContents* caches)
    : sc_core::sc_module(name), clock_(CycleClock::atMegahertz(config.clockMhz)) {
  validate(config);
  const std::string top = this->name();
  const size_t coreCount = static_cast<size_t>(config.cores);
  const uint64_t jobCount = records.size();

  hostJobs_ = std::make_unique<Channel<HostJob>>("host_jobs", clock_);
  pendingJobs_ = std::make_unique<Channel<CoreJob>>("pending_jobs", clock_);
  managedResults_ =
      std::make_unique<Channel<CoreResult>>("managed_results", clock_, OfferRule::MayWithdraw);
  traceChannel(*hostJobs_, trace, top + ".job_manager.in");
  traceChannel(*pendingJobs_, trace, top + ".scheduler.in");
  traceChannel(*managedResults_, trace, top + ".result_manager.out");

  source_ = std::make_unique<HostSource>("host_source", clock_, std::move(records), config.hostInput);
  source_->out(*hostJobs_);
  jobManager_ = std::make_unique<JobManager>("job_manager", clock_, config.jobManager, memory);
  jobManager_->in(*hostJobs_);
  jobManager_->out(*pendingJobs_);
  scheduler_ = std::make_unique<Scheduler>("scheduler", clock_, config.scheduler);
  scheduler_->in(*pendingJobs_);
  memory_ = std::make_unique<MemorySystem>("memory", clock_, memory, config.memory, config.cores,
                                           trace, caches);
  resultManager_ = std::make_unique<ResultManager>("result_manager", clock_);

  for (size_t i = 0; i < coreCount; ++i) {
    coreJobs_.push_back(std::make_unique<Channel<CoreJob>>(indexed("core_jobs_", i).c_str(), clock_));
    coreResults_.push_back(
        std::make_unique<Channel<CoreResult>>(indexed("core_results_", i).c_str(), clock_));
    const std::string coreName = indexed("core_", i);
    traceChannel(*coreJobs_[i], trace, top + "." + coreName + ".in");
    traceChannel(*coreResults_[i], trace, top + "." + coreName + ".out");
    cores_.push_back(std::make_unique<SvoTraversalCore>(coreName.c_str(), clock_, static_cast<int>(i),
                                                        config.jobManager.format,
                                                        config.stackFrames, trace));
    cores_[i]->in(*coreJobs_[i]);
    cores_[i]->out(*coreResults_[i]);
    cores_[i]->memory(*memory_);
    scheduler_->cores(*coreJobs_[i]);
    resultManager_->cores(*coreResults_[i]);
  }
  resultManager_->out(*managedResults_);

  Channel<CoreResult>* toHost = managedResults_.get();
  if (config.reorderCapacity > 0) {
    orderedResults_ = std::make_unique<Channel<CoreResult>>("ordered_results", clock_);
    traceChannel(*orderedResults_, trace, top + ".reorder_buffer.out");
    reorderBuffer_ = std::make_unique<ReorderBuffer>("reorder_buffer", clock_, config.reorderCapacity);
    reorderBuffer_->in(*managedResults_);
    reorderBuffer_->out(*orderedResults_);
    toHost = orderedResults_.get();
  }
  sink_ = std::make_unique<HostSink>("host_sink", clock_, jobCount, config.outputLink());
  sink_->in(*toHost);
}

}  // namespace rtu
