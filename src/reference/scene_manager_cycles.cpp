#include "reference/scene_manager_cycles.h"

#include <algorithm>
#include <optional>

#include "kinds/core_result.h"
#include "kinds/registry.h"
#include "reference/rtl_top.h"

namespace rtu {
namespace {

struct HeldRay {
  uint64_t id = 0;
  RayRecord record;
  std::vector<SceneCandidate> candidates;  // front to back
  size_t issued = 0;
  uint64_t readyFrom = 0;  // entry + latency
  std::optional<uint64_t> doneFrom;
  bool outstanding = false;
  CoreKindResult merged;
  int nearest = -1;
};

// Over the cores' kind, chosen once in runSceneCycles: the RTU below is RtlTop<Kind>.
template <class Kind>
class SceneCycles {
 public:
  SceneCycles(const WordMemory& memory, const std::vector<RayRecord>& rays,
              const std::vector<SceneInstance>& instances, const SceneManagerConfig& scene,
              const RtlTopConfig& rtu)
      : rays_(rays),
        instances_(instances),
        scene_(scene),
        coreConfigs_(rtu.coreConfigs),
        miss_(coreKindMiss(rtu.core)),
        top_(memory, rtu) {
    scene_.validate();
  }

  SceneCyclesRun run() {
    while (run_.arrivalCycles.size() < rays_.size()) cycle();
    run_.totalCycles = run_.arrivalCycles.empty() ? 0 : run_.arrivalCycles.back() + 1;
    return run_;
  }

 private:
  void cycle() {
    const uint64_t now = top_.cycle();
    if (delivered_) merge(*delivered_, now);
    takeRay(now);
    offerToHost(now);
    offerJob(now);
    const RtlCycle rtu = top_.step(jobOffer_ ? &*jobOffer_ : nullptr);
    // The clock edge.
    if (rtu.accepted) {
      run_.issueCycles.push_back(now);
      jobOffer_.reset();
    }
    delivered_ = rtu.delivered;
    if (hostOffer_) hostTakes(now);
  }

  std::vector<HeldRay>::iterator heldRay(uint64_t id) {
    return std::find_if(held_.begin(), held_.end(),
                        [id](const HeldRay& ray) { return ray.id == id; });
  }

  // A result delivered in the cycle before: the nearest hit so far, the costs summed.
  void merge(const RtlCycle::Delivery& delivery, uint64_t now) {
    HeldRay& ray = *heldRay(jobRay_[delivery.tag]);
    ray.outstanding = false;
    --jobsOutstanding_;
    const uint32_t instance = ray.candidates[ray.issued - 1].instance;
    const uint32_t cost = resultCost(ray.merged) + resultCost(delivery.result);
    if (nearerSceneHit(delivery.result, instance, ray.merged, ray.nearest)) {
      ray.merged = delivery.result;
      ray.nearest = static_cast<int>(instance);
    }
    setResultCost(ray.merged, cost);
    if (ray.issued == ray.candidates.size() || endsEarly(ray)) finish(ray, now);
  }

  bool endsEarly(const HeldRay& ray) const {
    return scene_.options.earlyTermination && ray.nearest >= 0 &&
           hitEndsRayBefore(hitDistance(ray.merged, coreConfigs_), ray.candidates[ray.issued].near);
  }

  void finish(HeldRay& ray, uint64_t from) {
    ray.doneFrom = from;
    const size_t left = ray.candidates.size() - ray.issued;
    ++run_.statistics.jobsPerRay[ray.issued];
    run_.statistics.skipped += left;
    if (left > 0) ++run_.statistics.earlyTerminations;
  }

  // The host's ray, when fewer than raysInFlight are held (a ray leaving in this cycle counts).
  void takeRay(uint64_t now) {
    if (nextRay_ == rays_.size() || held_.size() >= static_cast<size_t>(scene_.raysInFlight))
      return;
    HeldRay ray;
    ray.id = nextRay_;
    ray.record = rays_[nextRay_++];
    uint32_t culled = 0;
    ray.candidates = sceneCandidates(ray.record, instances_, scene_.options, culled);
    ray.readyFrom = now + static_cast<uint64_t>(scene_.latency);
    ray.merged = miss_(ray.record.id);
    ++run_.statistics.rays;
    run_.statistics.culled += culled;
    if (ray.candidates.empty()) finish(ray, ray.readyFrom);
    held_.push_back(ray);
  }

  void offerToHost(uint64_t now) {
    if (hostOffer_) return;
    for (const HeldRay& ray : held_)
      if (ray.doneFrom && *ray.doneFrom <= now) {
        hostOffer_ = ray.id;
        return;
      }
  }

  // The oldest ray that may issue its next instance.
  void offerJob(uint64_t now) {
    if (jobOffer_ || jobsOutstanding_ >= static_cast<uint64_t>(scene_.jobsOutstanding)) return;
    for (HeldRay& ray : held_) {
      if (ray.readyFrom > now || ray.outstanding || ray.doneFrom ||
          ray.issued == ray.candidates.size())
        continue;
      RayRecord job = ray.record;
      job.modelAddress = instances_[ray.candidates[ray.issued++].instance].headerAddress;
      jobOffer_ = RtlOffer{job, jobRay_.size()};
      jobRay_.push_back(ray.id);
      ray.outstanding = true;
      ++jobsOutstanding_;
      ++run_.statistics.jobs;
      return;
    }
  }

  void hostTakes(uint64_t now) {
    const auto ray = heldRay(*hostOffer_);
    run_.rays.push_back(ray->id);
    run_.results.push_back(ray->merged);
    run_.instances.push_back(ray->nearest);
    run_.arrivalCycles.push_back(now);
    held_.erase(ray);
    hostOffer_.reset();
  }

  const std::vector<RayRecord>& rays_;
  const std::vector<SceneInstance>& instances_;
  SceneManagerConfig scene_;
  CoreKindConfigs coreConfigs_;  // how the cores' kind set their jobs up: the hits' distances
  CoreKindMiss miss_;            // the cores' kind's
  RtlTop<Kind> top_;
  // Registers.
  size_t nextRay_ = 0;         // the ray the host offers
  std::vector<HeldRay> held_;  // oldest first
  std::optional<RtlOffer> jobOffer_;
  std::vector<uint64_t> jobRay_;  // per job id: its ray
  uint64_t jobsOutstanding_ = 0;  // offered and not merged
  std::optional<RtlCycle::Delivery> delivered_;
  std::optional<uint64_t> hostOffer_;  // the ray offered to the host
  SceneCyclesRun run_;
};

}  // namespace

SceneCyclesRun runSceneCycles(const WordMemory& memory, const std::vector<RayRecord>& rays,
                              const std::vector<SceneInstance>& instances,
                              const SceneManagerConfig& scene, const RtlTopConfig& rtu) {
  return withCoreKind(rtu.core, [&](auto kind) {
    return SceneCycles<decltype(kind)>(memory, rays, instances, scene, rtu).run();
  });
}

}  // namespace rtu
