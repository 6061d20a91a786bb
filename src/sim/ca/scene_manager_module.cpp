#include "sim/ca/scene_manager_module.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <variant>

namespace rtu {

SceneManagerModule::SceneManagerModule(sc_core::sc_module_name name, const CycleClock& clock,
                                       DecisionPump& pump, std::vector<SceneInstance> instances,
                                       const RtuConfig& config)
    : sc_core::sc_module(name),
      Agent(pump),
      clock_(clock),
      wake_(clock),
      instances_(std::move(instances)),
      config_(config.sceneManager),
      coreConfigs_(config.coreConfigs),
      miss_(coreKindMiss(config.core)) {
  config_.validate();
}

void SceneManagerModule::end_of_elaboration() {
  spawnReaction("decide", [this] { pump().runWith(*this); }, {&wake_.event()});
}

void SceneManagerModule::bind(TransferChannel<HostPayload>& raysIn,
                              TransferChannel<HostPayload>& jobsOut,
                              TransferChannel<CoreResult>& resultsIn,
                              TransferChannel<CoreResult>& raysOut) {
  raysIn_ = &raysIn;
  jobsOut_ = &jobsOut;
  resultsIn_ = &resultsIn;
  raysOut_ = &raysOut;
  resultsIn_->readyAlways();
  resultsIn_->traceReady(0, true);
}

void SceneManagerModule::decide() {
  const uint64_t now = clock_.now();
  if (jobsOut_->collectTaken()) {
    issueFrom_ = jobsOut_->lastTransfer() + 1;
    issueCycles_.push_back(jobsOut_->lastTransfer());
  }
  if (raysOut_->collectTaken()) {
    hostFrom_ = raysOut_->lastTransfer() + 1;
    leaving_.push_back(raysOut_->lastTransfer());
    rays_.erase(std::find_if(rays_.begin(), rays_.end(),
                             [this](const Ray& ray) { return ray.id == offeredRay_; }));
  }
  resultsIn_->collectDelivered(
      [this](uint64_t cycle, const CoreResult& result) { arriving_.emplace(cycle, result); });
  if (resultsIn_->offering()) {  // from a reorder buffer: always ready, so taken as offered
    const uint64_t cycle = resultsIn_->offerCycle();
    arriving_.emplace(cycle, resultsIn_->payload());
    resultsIn_->take(cycle);
  }
  while (!leaving_.empty() && leaving_.front() < now) leaving_.pop_front();
  mergeResults(now);
  takeRay(now);
  offerToHost(now);
  issue(now);
  wakeForNext(now);
}

// Results delivered before this cycle.
void SceneManagerModule::mergeResults(uint64_t now) {
  while (!arriving_.empty() && arriving_.begin()->first < now) {
    merge(arriving_.begin()->second, arriving_.begin()->first);
    arriving_.erase(arriving_.begin());
  }
}

SceneManagerModule::Ray& SceneManagerModule::rayWithId(uint64_t id) {
  const auto found =
      std::find_if(rays_.begin(), rays_.end(), [id](const Ray& ray) { return ray.id == id; });
  if (found == rays_.end())
    throw std::logic_error("scene manager: a result for ray " + std::to_string(id) +
                           ", which is not in flight");
  return *found;
}

void SceneManagerModule::merge(const CoreResult& result, uint64_t cycle) {
  Ray& ray = rayWithId(result.ids.ray);
  ray.outstanding = false;
  --jobsOutstanding_;
  const uint32_t instance = ray.candidates[ray.next - 1].instance;
  const uint32_t cost = resultCost(ray.merged.result) + resultCost(result.result);
  ray.merged.blockedCycles += result.blockedCycles;
  if (nearerSceneHit(result.result, instance, ray.merged.result, ray.nearest)) {
    ray.merged.result = result.result;
    ray.nearest = static_cast<int>(instance);
    ray.merged.instance = ray.nearest;
  }
  setResultCost(ray.merged.result, cost);
  const bool allIssued = ray.next == ray.candidates.size();
  const bool ended =
      !allIssued && config_.options.earlyTermination && ray.nearest >= 0 &&
      hitEndsRayBefore(hitDistance(ray.merged.result, coreConfigs_), ray.candidates[ray.next].near);
  if (allIssued || ended) finish(ray, cycle + 1);
}

void SceneManagerModule::finish(Ray& ray, uint64_t cycle) {
  ray.doneFrom = cycle;
  const uint64_t skipped = ray.candidates.size() - ray.next;
  ++statistics_.jobsPerRay[ray.next];
  statistics_.skipped += skipped;
  if (skipped > 0) ++statistics_.earlyTerminations;
}

// The oldest finished ray, from the cycle after the last transfer to the host.
void SceneManagerModule::offerToHost(uint64_t now) {
  if (raysOut_->offering() || hostFrom_ > now) return;
  for (const Ray& ray : rays_) {
    if (ray.doneFrom > now) continue;
    offeredRay_ = ray.id;
    raysOut_->offer(ray.merged, now);
    return;
  }
}

uint64_t SceneManagerModule::heldIn(uint64_t cycle) const {
  // A ray the host took in cycle k is held through k.
  return rays_.size() +
         static_cast<uint64_t>(std::count_if(leaving_.begin(), leaving_.end(),
                                             [cycle](uint64_t left) { return left >= cycle; }));
}

void SceneManagerModule::takeRay(uint64_t now) {
  if (!raysIn_->offering() || raysIn_->offerCycle() > now || takeFrom_ > now ||
      heldIn(now) >= static_cast<uint64_t>(config_.raysInFlight))
    return;
  const HostPayload host = raysIn_->payload();
  const RayRecord* record = std::get_if<RayRecord>(&host.record);
  if (!record)
    throw std::invalid_argument("scene manager: host record " + std::to_string(host.ids.ray) +
                                " is a t-value record; a scene needs ray records");
  raysIn_->take(now);
  takeFrom_ = now + 1;
  Ray ray;
  ray.id = host.ids.ray;
  ray.record = *record;
  uint32_t culled = 0;
  ray.candidates = sceneCandidates(ray.record, instances_, config_.options, culled);
  ray.readyFrom = now + static_cast<uint64_t>(config_.latency);
  ray.merged.ids = PayloadIds::plain(ray.id);
  ray.merged.result = miss_(record->id);
  ++statistics_.rays;
  statistics_.culled += culled;
  rays_.push_back(ray);
  if (rays_.back().candidates.empty()) finish(rays_.back(), rays_.back().readyFrom);
}

// The oldest ray with a job to issue.
void SceneManagerModule::issue(uint64_t now) {
  if (jobsOut_->offering() || issueFrom_ > now ||
      jobsOutstanding_ >= static_cast<uint64_t>(config_.jobsOutstanding))
    return;
  for (Ray& ray : rays_) {
    if (!wantsJob(ray) || ray.readyFrom > now) continue;
    RayRecord job = ray.record;
    job.modelAddress = instances_[ray.candidates[ray.next].instance].headerAddress;
    jobsOut_->offer(HostPayload{PayloadIds{ray.id, nextJob_++}, job}, now);
    ++ray.next;
    ray.outstanding = true;
    ++jobsOutstanding_;
    ++statistics_.jobs;
    return;
  }
}

bool SceneManagerModule::wantsJob(const Ray& ray) const {
  return !ray.outstanding && ray.doneFrom == kNeverCycle && ray.next < ray.candidates.size();
}

// The next cycle in which a rule may fire without news from a channel.
void SceneManagerModule::wakeForNext(uint64_t now) {
  uint64_t next = kNeverCycle;
  const auto consider = [&next, now](uint64_t cycle) {
    if (cycle > now) next = std::min(next, cycle);
  };
  if (!arriving_.empty()) consider(arriving_.begin()->first + 1);
  if (!raysOut_->offering())
    for (const Ray& ray : rays_)
      if (ray.doneFrom != kNeverCycle) consider(std::max(ray.doneFrom, hostFrom_));
  if (raysIn_->offering()) {
    const uint64_t from = std::max(raysIn_->offerCycle(), takeFrom_);
    if (heldIn(std::max(from, now)) < static_cast<uint64_t>(config_.raysInFlight))
      consider(from);
    else if (!leaving_.empty())
      consider(leaving_.front() + 1);
  }
  if (!jobsOut_->offering() && jobsOutstanding_ < static_cast<uint64_t>(config_.jobsOutstanding))
    for (const Ray& ray : rays_)
      if (wantsJob(ray)) consider(std::max(ray.readyFrom, issueFrom_));
  if (next != kNeverCycle) wake_.at(next);
}

}  // namespace rtu
