#include "sim/ca/rtu_top.h"

#include <string>

namespace rtu {
namespace {

std::string indexed(const char* base, size_t index) { return base + std::to_string(index); }

template <class Payload>
std::unique_ptr<TransferChannel<Payload>> channel(const std::string& name, const CycleClock& clock,
                                                  CycleTrace* trace, const std::string& scope) {
  auto made = std::make_unique<TransferChannel<Payload>>(name, clock);
  if (trace) made->trace(*trace, scope);
  return made;
}

// The cores' triangle units: shared by groups of core.triangle.shared_by, or one a core.
TriangleUnitArbiter triangleUnits(const RtuConfig& config) {
  if (!config.trianglesShared()) return TriangleUnitArbiter(config.cores, 1, 1);
  const uint32_t interval = withCoreKind(config.core, [&config](auto kind) {
    return triangleIntervalOf<decltype(kind)>(config.coreConfig<decltype(kind)>());
  });
  return TriangleUnitArbiter(config.cores, config.triangleSharedBy, interval);
}

}  // namespace

RtuTop::RtuTop(sc_core::sc_module_name name, const RtuConfig& config, WordMemory memory,
               const RecordSource& records, CycleTrace* trace, const CacheContents* caches,
               const std::vector<SceneInstance>* scene, HostSink::Take take)
    : sc_core::sc_module(name), clock_(CycleClock::atMegahertz(config.clockMhz)) {
  validate(config);
  const std::string top = this->name();
  const size_t coreCount = static_cast<size_t>(config.cores);
  const uint64_t jobCount = records.size();

  hostJobs_ = channel<HostPayload>("host_jobs", clock_, trace, top + ".job_manager.in");
  pendingJobs_ = channel<CoreJob>("pending_jobs", clock_, trace, top + ".scheduler.in");
  managedResults_ =
      channel<CoreResult>("managed_results", clock_, trace, top + ".result_manager.out");

  source_ = std::make_unique<HostSource>("host_source", clock_, pump_, records, config.hostInput,
                                         kLookAheadCycles);
  jobManager_ = std::make_unique<JobManager>(
      pump_, clock_, config.jobManager,
      makeCoreJobSetup(config.core, memory, config.jobManager, config.coreConfigs));
  scheduler_ = std::make_unique<Scheduler>(pump_, config.scheduler, config.cores);
  // The cores' kind decides when an idle core reads first; the cores are made by makeTimedCore.
  const uint64_t firstRead =
      withCoreKind(config.core, [](auto kind) { return decltype(kind)::kFirstReadAfterDispatch; });
  memory_ =
      std::make_unique<MemorySystem>("memory", clock_, pump_, memory, config.memory, config.cores,
                                     firstRead, triangleUnits(config), trace, caches);
  memory_->followDispatches(*scheduler_);
  resultManager_ = std::make_unique<ResultManager>("result_manager", clock_, pump_);
  if (scene) {
    sceneRays_ = channel<HostPayload>("scene_rays", clock_, trace, top + ".scene_manager.in");
    rayResults_ = channel<CoreResult>("ray_results", clock_, trace, top + ".scene_manager.out");
    sceneManager_ =
        std::make_unique<SceneManagerModule>("scene_manager", clock_, pump_, *scene, config);
    sceneRays_->connect(*source_, HostSource::kOutPort, *sceneManager_,
                        SceneManagerModule::kRaysInPort);
    hostJobs_->connect(*sceneManager_, SceneManagerModule::kJobsOutPort, *jobManager_,
                       JobManager::kInPort);
  } else {
    hostJobs_->connect(*source_, HostSource::kOutPort, *jobManager_, JobManager::kInPort);
  }
  pendingJobs_->connect(*jobManager_, JobManager::kOutPort, *scheduler_, Scheduler::kJobsPort);

  std::vector<Channel<CoreJob>*> jobsToCores;
  std::vector<Channel<CoreResult>*> resultsFromCores;
  for (size_t i = 0; i < coreCount; ++i) {
    const std::string coreName = indexed("core_", i);
    coreJobs_.push_back(
        channel<CoreJob>(indexed("core_jobs_", i), clock_, trace, top + "." + coreName + ".in"));
    coreResults_.push_back(channel<CoreResult>(indexed("core_results_", i), clock_, trace,
                                               top + "." + coreName + ".out"));
    cores_.push_back(makeTimedCore(config, coreName.c_str(), pump_, static_cast<int>(i), trace));
    cores_[i]->memory(*memory_);
    coreJobs_[i]->connect(*scheduler_, static_cast<int>(i), *cores_[i], TimedCoreBase::kJobsPort);
    coreResults_[i]->connect(*cores_[i], TimedCoreBase::kResultsPort, *resultManager_,
                             static_cast<int>(i));
    jobsToCores.push_back(coreJobs_[i].get());
    resultsFromCores.push_back(coreResults_[i].get());
  }

  Channel<CoreResult>* toHost = managedResults_.get();
  sink_ = std::make_unique<HostSink>(pump_, jobCount, config.outputLink(), std::move(take));
  if (config.reorderCapacity > 0) {
    orderedResults_ =
        channel<CoreResult>("ordered_results", clock_, trace, top + ".reorder_buffer.out");
    reorderBuffer_ = std::make_unique<ReorderBuffer>(pump_, clock_, config.reorderCapacity);
    managedResults_->connect(*resultManager_, ResultManager::kOutPort, *reorderBuffer_,
                             ReorderBuffer::kInPort);
    toHost = orderedResults_.get();
  }
  // The RTU's results go to the host, or through the scene manager, which merges them per ray.
  Agent& resultsConsumer = sceneManager_ ? static_cast<Agent&>(*sceneManager_) : *sink_;
  const int resultsPort = sceneManager_ ? SceneManagerModule::kResultsInPort : HostSink::kInPort;
  if (reorderBuffer_)
    orderedResults_->connect(*reorderBuffer_, ReorderBuffer::kOutPort, resultsConsumer,
                             resultsPort);
  else
    managedResults_->connect(*resultManager_, ResultManager::kOutPort, resultsConsumer,
                             resultsPort);
  if (sceneManager_) {
    rayResults_->connect(*sceneManager_, SceneManagerModule::kRaysOutPort, *sink_,
                         HostSink::kInPort);
    sceneManager_->bind(*sceneRays_, *hostJobs_, *toHost, *rayResults_);
    toHost = rayResults_.get();
  }

  source_->bind(sceneManager_ ? *sceneRays_ : *hostJobs_);
  jobManager_->bind(*hostJobs_, *pendingJobs_);
  scheduler_->bind(*pendingJobs_, jobsToCores);
  for (size_t i = 0; i < coreCount; ++i) cores_[i]->bind(*coreJobs_[i], *coreResults_[i]);
  resultManager_->bind(resultsFromCores, *managedResults_);
  if (reorderBuffer_) reorderBuffer_->bind(*managedResults_, *orderedResults_);
  sink_->bind(*toHost);
}

}  // namespace rtu
