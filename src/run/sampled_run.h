#pragma once
// Sampled simulation (as SMARTS, Wunderlich et al. 2003): a frame's total cycles, cycles per ray
// and cache hit rates estimated with a 95 % confidence interval from a stratified sample of ray
// blocks, each simulated cycle-accurately after a warm-up that is simulated but not counted.
//
// The frame's rays, in the order the host submits them (scan lines, so a stretch of rays is a
// band of the image), split into
//   head     the first block, simulated from reset: the pipeline's fill;
//   strata   S equal stretches of the rest but the last block; two blocks at random places in
//            each (seeded), each after the `warmup` rays before it;
//   tail     the last block after its warm-up: the drain at the end of the frame.
// Before each block's warm-up, the caches are brought up to date functionally with every ray
// since the previous block (cache_warmer.h), so a short warm-up suffices. A block counts from the
// snapshot after its warm-up's results to the snapshot after its own (rtu_simulation.h
// BlockRun), a few `cooldown` rays keeping the cores busy to its end: cycles per result, and
// counters per result (statistics_window.h).
// Per-ray values y of the blocks are adjusted by a regression on the golden model's cost x (of the
// run's kind), known for every ray: y' = y + b (X_h - x), with X_h the stratum's mean cost and b
// the slope pooled within strata (Cochran, Sampling Techniques, 7.9). With R_h rays in stratum h:
//   total  = B (y_head + y_tail) + sum_h R_h mean_j(y'_hj)
//   var    = sum_h R_h^2 s^2 / 2 + (sum_h R_h (X_h - mean_j x_hj))^2 s^2 / Sxx
//            (s^2: the blocks' deviations from their stratum means, pooled, 2S - S - 1 degrees)
//   95 %   = total +- t(0.975, S - 1) sqrt(var)
// and a hit rate is a ratio of two such totals (hits and accesses), its variance linearised.
// docs/fidelity.md measures the estimates against full runs.

#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "run/rtu_simulation.h"

namespace rtu {

// What to sample.
struct SampleSpec {
  double fraction = 0;  // of the frame's rays simulated, warm-ups included; 0: every ray
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

  // The "sample" object of the statistics JSON: the plan and the 95 % intervals.
  static const StatisticGroup<SampledRun>& declaration();
};

// The statistics JSON of a run (RtuStatistics::toJson) for the frame: rays, total cycles and
// what follows from them (cycles per ray, frame time, frame rate, DRAM bytes) and the hit rates
// are the frame's estimates; ratios come from the counted blocks; "sample" holds the plan and the
// 95 % intervals; "simulation.model" is "sampled".
nlohmann::ordered_json sampledStatisticsJson(const SampledRun& run);

// The frame's records are any the run's kind (config.core) takes; its cache warmer and the golden
// costs are that kind's.
SampledRun runSampled(const WordMemory& memory, const std::vector<HostRecord>& jobs,
                      const RtuConfig& config, const SampleSpec& spec);

// The 97.5 % quantile of Student's t with `degrees` degrees of freedom (Cornish-Fisher expansion:
// within 1 % from 3 degrees on, 0.1 % from 6).
double studentT975(int degrees);

}  // namespace rtu
