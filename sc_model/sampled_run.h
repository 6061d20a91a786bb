#pragma once
// Sampled simulation (as SMARTS, Wunderlich et al. 2003): a frame's total cycles, cycles per ray
// and cache hit rates estimated with a 95 % confidence interval from a stratified sample of ray
// blocks, each simulated cycle-accurately after a warm-up that is simulated but not counted.
//
// The frame's rays, in the order the host submits them (scan lines, so a stretch of rays is a
// band of the image), split into
//   head     the first block, simulated from reset: the pipeline's fill, counted exactly;
//   strata   S equal stretches of the rest but the last block; two blocks at random places in
//            each, each after the `warmup` rays before it;
//   tail     the last block after its warm-up: the drain at the end of the frame.
// A block counts the cycles from the arrival of its warm-up's last result to that of its own last
// result, and the counters in between (statistics_window.h: the counters of a run of warm-up and
// block less those of a run of the warm-up alone). With m_h = rays_h / block the block slots of
// stratum h and c_hj its blocks' cycles:
//   total  = head + tail + sum_h m_h mean_j(c_hj)
//   var    = sum_h m_h^2 (1 - 2 / m_h) s_h^2 / 2       (s_h^2: the two blocks' sample variance)
//   95 %   = total +- t(0.975, S) sqrt(var)
// and a hit rate is a ratio of two such totals (hits and accesses), its variance linearised.
// docs/fidelity.md measures the estimates against full runs.

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "rtu_simulation.h"

namespace rtu {

// What to sample.
struct SampleSpec {
  double fraction = 0;      // of the frame's rays simulated, warm-ups included; 0: every ray
  uint64_t seed = 1;
  uint64_t blockRays = 0;   // rays counted per block; 0: chosen from the fraction
  uint64_t warmupRays = 0;  // rays simulated before each block, not counted; 0: 4096

  bool enabled() const { return fraction > 0; }
};


struct SamplePlan {
  uint64_t rays = 0;
  uint64_t blockRays = 0, warmupRays = 0;
  uint64_t cooldownRays = 0;  // after a block, keeping the cores busy to its end
  struct Stratum {
    uint64_t first = 0, rays = 0;
    std::vector<uint64_t> blocks;  // first rays of its sampled blocks
  };
  std::vector<Stratum> strata;
  uint64_t tailFirst = 0;

  uint64_t blockCost() const;  // rays simulated for a block: warm-up, block, cool-down
  uint64_t simulatedRays() const;
};

// The plan for `rays` rays; throws std::invalid_argument naming the sample settings when the
// fraction leaves too few rays for two strata of two blocks.
SamplePlan planSample(uint64_t rays, int cores, const SampleSpec& spec);

struct Interval {
  double estimate = 0, low = 0, high = 0;
};

struct SampledRun {
  SamplePlan plan;
  Interval totalCycles, l1HitRate, l2HitRate;
  // The counted parts together: their rays, cycles and counters (statistics_window.h), the
  // ratios (cycles per ray, time shares, hit rates) estimated from the sample.
  RtuStatistics counted;
  double hostSeconds = 0;
};

// The statistics JSON of a run (RtuStatistics::toJson) for the frame: rays, total cycles and
// what follows from them (cycles per ray, frame time, frame rate, DRAM bytes) and the hit rates
// are the frame's estimates; ratios come from the counted blocks; "sample" holds the plan and the
// 95 % intervals; "simulation.model" is "sampled".
nlohmann::ordered_json sampledStatisticsJson(const SampledRun& run);

SampledRun runSampled(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
                      const RtuConfig& config, const SampleSpec& spec);

// The 97.5 % quantile of Student's t with `degrees` degrees of freedom (Cornish-Fisher expansion:
// within 1 % from 3 degrees on, 0.1 % from 6).
double studentT975(int degrees);

}  // namespace rtu
