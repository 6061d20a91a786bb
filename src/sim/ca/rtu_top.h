#pragma once
// The RTU of thesis figure 6.1 (appendix C.1) with its host: source -> job manager -> scheduler ->
// N traversal cores (reading the memory system) -> result manager [-> reorder buffer] -> sink,
// every arrow a transfer channel. A scene puts the scene manager between the host and the RTU:
// source -> scene manager -> job manager, result manager [-> reorder buffer] -> scene manager ->
// sink; it issues jobs per instance and hands the host one merged result per ray. Every arrow is a
// transfer channel (src/sim/kernel/transfer_channel.h), every module deciding through one
// decision pump (src/sim/kernel/decision_pump.h).

#include <memory>
#include <vector>

#include <systemc>

#include "sim/ca/host_sink.h"
#include "sim/ca/host_source.h"
#include "sim/ca/job_manager.h"
#include "sim/ca/memory_system.h"
#include "sim/ca/reorder_buffer.h"
#include "sim/ca/result_manager.h"
#include "sim/ca/scene_manager_module.h"
#include "sim/ca/scheduler.h"
#include "sim/ca/timed_core.h"
#include "sim/kernel/cycle_clock.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/transfer_channel.h"
#include "sim/rtu_config.h"
#include "trace/cycle_trace.h"

namespace rtu {

class RtuTop : public sc_core::sc_module {
 public:
  // `memory`, `records` and the trace must outlive the top; `trace` may be null.
  // `caches`: lines resident from cycle 0 (sampled simulation), or null. `scene`: the instances
  // the host's ray records are traced against, or null for records each traced once.
  RtuTop(sc_core::sc_module_name name, const RtuConfig& config, WordMemory memory,
         const RecordSource& records, CycleTrace* trace, const CacheContents* caches = nullptr,
         const std::vector<SceneInstance>* scene = nullptr, HostSink::Take take = {});

  // How far ahead of simulated time the host source offers records.
  static constexpr uint64_t kLookAheadCycles = 4096;

  HostSink& sink() { return *sink_; }
  const HostSink& sink() const { return *sink_; }
  const JobManager& jobManager() const { return *jobManager_; }
  const Scheduler& scheduler() const { return *scheduler_; }
  const MemorySystem& memory() const { return *memory_; }
  const std::vector<std::unique_ptr<TimedCoreBase>>& cores() const { return cores_; }
  const ResultManager& resultManager() const { return *resultManager_; }
  const ReorderBuffer* reorderBuffer() const { return reorderBuffer_.get(); }
  const SceneManagerModule* sceneManager() const { return sceneManager_.get(); }

 private:
  template <class Payload>
  using Channel = TransferChannel<Payload>;

  CycleClock clock_;
  DecisionPump pump_;
  std::unique_ptr<Channel<HostPayload>> hostJobs_;
  std::unique_ptr<Channel<CoreJob>> pendingJobs_;
  std::vector<std::unique_ptr<Channel<CoreJob>>> coreJobs_;
  std::vector<std::unique_ptr<Channel<CoreResult>>> coreResults_;
  std::unique_ptr<Channel<CoreResult>> managedResults_, orderedResults_;
  std::unique_ptr<Channel<HostPayload>> sceneRays_;
  std::unique_ptr<Channel<CoreResult>> rayResults_;

  std::unique_ptr<HostSource> source_;
  std::unique_ptr<JobManager> jobManager_;
  std::unique_ptr<Scheduler> scheduler_;
  std::unique_ptr<MemorySystem> memory_;
  std::vector<std::unique_ptr<TimedCoreBase>> cores_;
  std::unique_ptr<ResultManager> resultManager_;
  std::unique_ptr<ReorderBuffer> reorderBuffer_;
  std::unique_ptr<SceneManagerModule> sceneManager_;
  std::unique_ptr<HostSink> sink_;
};

}  // namespace rtu
