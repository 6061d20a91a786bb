#pragma once
// Everything that configures one simulated RTU. The defaults are the thesis configuration: 16
// cores, cyclic first-available scheduling, ideal memory, Q16.16 with the RTL's conversion, an
// 11-frame stack, unlimited host links, results in completion order, 100 MHz.

#include <optional>
#include <string>

#include "kinds/registry.h"
#include "rtu/host_link.h"
#include "rtu/job_manager_timing.h"
#include "rtu/scheduling_policy.h"
#include "scene/scene_manager_timing.h"
#include "sim/memory/memory_config.h"
#include "trace/cycle_trace.h"
#include "trace/timeline_writer.h"

namespace rtu {

struct RtuConfig {
  std::string core = SvoKind::kName;  // the kind of traversal core (kinds/registry.h)
  int cores = 16;
  SchedulerPolicy scheduler = SchedulerPolicy::CyclicFirstAvailable;
  MemoryConfig memory = idealMemory();
  JobManagerTiming jobManager;
  CoreKindConfigs coreConfigs;  // every kind's own settings (SVO's: format, stack, ...)
  // core.triangle.shared_by: cores per ray/triangle unit, a kind with one (rtu/core_kind.h); cores
  // i*N .. i*N+N-1 share unit i, round-robin (the last group smaller when N does not divide the
  // cores). 1: a unit per core.
  int triangleSharedBy = 1;
  HostLinkConfig hostInput, hostOutput;
  int reorderCapacity = 0;  // 0: no reorder buffer
  // warm_frames: frames of the same records run through the caches before the measured one
  // (functional warming, run/warm_frames.h); 0: the frame starts from cold caches.
  int warmFrames = 0;
  SceneManagerConfig sceneManager;  // used when the run traces a scene
  double clockMhz = 100.0;
  uint64_t ltQuantum = 1000;  // loosely-timed model: global quantum in cycles (lt.quantum)
  std::optional<TraceOptions> trace;
  TimelineOptions timeline;  // path empty: no timeline

  static MemoryConfig idealMemory() {
    MemoryConfig memory;
    memory.ideal = true;
    return memory;
  }
  // The settings of a core of `Kind` (a test's kind outside the registry: its defaults).
  template <class Kind>
  const typename Kind::Config& coreConfig() const {
    return CoreKinds::configOf<Kind>(coreConfigs);
  }
  template <class Kind>
  typename Kind::Config& coreConfig() {
    return CoreKinds::configOf<Kind>(coreConfigs);
  }
  // Whether cores of the chosen kind share a triangle unit (triangleSharedBy > 1 with a kind that
  // has one).
  bool trianglesShared() const;
  // The output link as results of the chosen kind cross it (SVO: 48-byte records over 32 bits).
  HostLinkConfig outputLink() const;
};

// Throws std::invalid_argument with a message naming the setting for impossible configurations.
// The most warm frames a run takes: each costs one untimed pass over the frame's rays.
constexpr int kMaxWarmFrames = 100;

void validate(const RtuConfig& config);

constexpr int kMaxCores = 1024;

}  // namespace rtu
