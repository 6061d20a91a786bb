#pragma once
// Frames of an animated scene on the untimed models: each frame's camera and instance headers
// from the scene description, every pixel's ray through the scene manager
// (src/scene/scene_manager.h) in parallel threads, the hit buffer (src/scene/hit_buffer.h) carried
// from frame to frame, and the frame's statistics. Cycles are the golden costs of the issued jobs
// run through the RTU recurrence (src/rtu/rtu_recurrence.h: ideal memory, the job manager's
// latencies, the chosen cores and cyclic first-available scheduling) in the order the scene manager
// issues them; the scene manager's own sphere tests and the hit buffer's checks are not timed.
//
// On the cycle-accurate model (AnimationOptions::rtu) the rays the hit buffer does not answer
// are also simulated through the SystemC scene manager (src/run/rtu_simulation.h
// simulateScene): its nearest hits make the picture and its simulated cycles the frame's.

#include <cstdint>
#include <optional>
#include <vector>

#include "base/statistics.h"
#include "run/model_run.h"
#include "scene/hit_buffer.h"
#include "scene/scene_file.h"
#include "scene/scene_memory.h"
#include "sim/rtu_config.h"

namespace rtu {

struct AnimationOptions {
  GoldenConfig golden;
  SceneManagerOptions manager;
  bool hitBuffer = true;
  int threads = 1;
  int cores = 16;
  double clockMhz = 100.0;
  // Which model times the frames: golden (its costs in the recurrence), ca (the SystemC scene
  // manager and RTU answer and time them) or lt (the golden scene manager's jobs, in pixel
  // order, through the loosely-timed RTU). `rtu` is set for ca and lt.
  ModelKind model = ModelKind::Golden;
  const RtuConfig* rtu = nullptr;
};

// A frame's statistics, declared (base/statistics.h) in the order of the per-frame CSV's columns;
// frames sum with sumOf().
struct FrameStatistics {
  int frame = 0;
  double time = 0.0;  // seconds into the animation
  uint64_t pixels = 0;
  uint64_t raysTraced = 0;  // pixels the scene manager traced
  uint64_t raysSaved = 0;   // pixels the hit buffer answered
  uint64_t hits = 0;
  uint64_t jobs = 0;
  uint64_t culled = 0;             // instance tests that missed the bounding sphere
  uint64_t earlyTerminations = 0;  // rays ended with instances left untraced
  uint64_t skipped = 0;            // instances left untraced by those rays
  uint64_t traversalCycles = 0;    // sum of the traced jobs' golden costs
  uint64_t cycles = 0;             // the frame's total on the RTU (recurrence or simulated)
  double hostSeconds = 0.0;
  double clockMhz = 100.0;  // of frameMs() and framesPerSecond()

  double jobsPerRay() const { return raysTraced ? static_cast<double>(jobs) / raysTraced : 0.0; }
  double frameMs() const { return cycles / (clockMhz * 1e3); }
  double framesPerSecond() const { return cycles ? clockMhz * 1e6 / cycles : 0.0; }

  static const StatisticGroup<FrameStatistics>& declaration();
};

struct SceneFrame {
  Camera camera;
  std::vector<ModelPlacement> placements;  // per instance
  std::vector<SceneHit> pixels;            // x + y * width
  FrameStatistics statistics;
};

class AnimationRenderer {
 public:
  AnimationRenderer(const SceneDescription& scene, const std::vector<SceneModel>& models,
                    AnimationOptions options);

  // Frames must come in order for the hit buffer to help; any order gives the same images.
  SceneFrame render(int frame);
  // Leaves the hit buffer as rendering every frame up to `frame` would: it keeps each pixel's
  // last answer, which the golden scene manager gives without simulating (the cycle-accurate
  // one answers the same). A renderer that starts in the middle of a sequence primes itself
  // with the frame before.
  void prime(int frame);

 private:
  struct Work;
  Work trace(int frame, SceneFrame& result);
  void remember(const SceneFrame& frame, const Work& work);
  void traceRows(Work& work, int firstRow, int rowStep);
  uint64_t frameCycles(const std::vector<std::vector<IssuedJob>>& issuedPerRow) const;
  // Simulates the rays `traced` on the cycle-accurate model; their pixels become its answers.
  uint64_t simulateFrame(Work& work, const std::vector<uint32_t>& traced) const;
  uint64_t looselyTimedCycles(const Work& work) const;

  const SceneDescription& scene_;
  AnimationOptions options_;
  SceneMemory memory_;
  HitBuffer hitBuffer_;
  std::optional<Camera> lastCamera_;
  std::vector<ModelHeaderWords> lastHeaders_;
};

}  // namespace rtu
