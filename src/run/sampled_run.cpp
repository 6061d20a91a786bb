#include "run/sampled_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>

#include "kinds/core_result.h"
#include "run/analytic_run.h"
#include "run/cache_warmer.h"
#include "run/statistics_output.h"
#include "run/statistics_window.h"

namespace rtu {
namespace {

constexpr uint64_t kMinBlockRays = 1024,
                   kMaxBlockRays = 4096;  // docs/fidelity.md: shorter ones are noisy
// Simulated before each block: fills the pipeline and the cores, and gives each L1 the rays its
// core really takes; the caches are warmed functionally before it (cache_warmer.h). 512 rays, or
// 32 a core: with 8 a core, 64 cores' L1s stayed colder than in the full run (docs/fidelity.md).
uint64_t defaultWarmupRays(int cores) {
  return std::max<uint64_t>(512, 32 * static_cast<uint64_t>(cores));
}
constexpr uint64_t kTargetStrata = 40;

uint64_t autoBlockRays(double budget, uint64_t warmup, uint64_t cooldown) {
  // head, tail and two blocks in each of kTargetStrata strata
  const double perBlock =
      budget / (2.0 * kTargetStrata + 2.0) - static_cast<double>(warmup + cooldown);
  return std::clamp<uint64_t>(static_cast<uint64_t>(std::max(perBlock, 0.0)), kMinBlockRays,
                              kMaxBlockRays);
}

std::string shortText(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

[[noreturn]] void tooFew(uint64_t rays, const SampleSpec& spec, uint64_t block, uint64_t warmup) {
  throw std::invalid_argument(
      "sample.fraction " + shortText(spec.fraction) + " of " + std::to_string(rays) +
      " rays is too small for two strata of two blocks of " + std::to_string(block) +
      " rays after a warm-up of " + std::to_string(warmup) +
      ": raise sample.fraction or lower "
      "sample.block / sample.warmup, or simulate every ray");
}

// What one block counted: its cycles, the results that arrived in them and its counters.
struct Block {
  double rays = 0, cycles = 0;
  RtuStatistics counted;
};

std::vector<HostRecord> slice(const std::vector<HostRecord>& jobs, uint64_t first, uint64_t end) {
  return {jobs.begin() + static_cast<ptrdiff_t>(first), jobs.begin() + static_cast<ptrdiff_t>(end)};
}

// The window between two snapshots (or a snapshot and the run's end).
Block between(const RunSnapshot& from, uint64_t toCycle, uint64_t toResults,
              const RtuStatistics& toStatistics) {
  Block block;
  block.rays = static_cast<double>(toResults - from.results);
  block.cycles = static_cast<double>(toCycle - from.cycle);
  block.counted = statisticsAfter(toStatistics, from.statistics, toResults - from.results,
                                  toCycle - from.cycle);
  return block;
}

// Rays [first, first + count) after up to `warmup` rays before them and followed by `cooldown`
// rays that keep the cores busy to its end; a block ending the frame runs to the last result.
Block simulateBlock(const WordMemory& memory, const std::vector<HostRecord>& jobs,
                    const RtuConfig& config, uint64_t first, uint64_t count, uint64_t warmup,
                    uint64_t cooldown, BlockRun plan) {
  const uint64_t warmFirst = first - std::min(warmup, first);
  const uint64_t warm = first - warmFirst;
  const uint64_t end = std::min<uint64_t>(jobs.size(), first + count + cooldown);
  if (warm > 0) plan.afterResults.push_back(warm);
  const bool endsFrame = end == jobs.size();
  if (!endsFrame) plan.afterResults.push_back(warm + count);
  plan.stopAtLast = !endsFrame;
  const RtuRun run = simulateRtu(memory, slice(jobs, warmFirst, end), config, plan);
  const RunSnapshot start = warm > 0 ? run.snapshots.front() : RunSnapshot{};
  if (endsFrame) return between(start, run.totalCycles, end - warmFirst, run.statistics);
  const RunSnapshot& stop = run.snapshots.back();
  return between(start, stop.cycle, stop.results, stop.statistics);
}

// The caches brought up to date with the frame's rays before `end` (one call per block, in frame
// order) by the cache warmer of the run's kind.
using WarmUp = std::function<const CacheContents*(uint64_t end)>;

WarmUp makeWarmUp(const WordMemory& memory, const std::vector<HostRecord>& jobs,
                  const RtuConfig& config) {
  return withCoreKind(config.core, [&](auto kind) -> WarmUp {
    auto warmer = std::make_shared<CacheWarmer<decltype(kind)>>(memory, config);
    warmer->warmFrames(jobs, config.warmFrames);  // then each block's rays before it
    return [warmer, &jobs](uint64_t end) {
      warmer->warmUpTo(jobs, end);
      return &warmer->contents();
    };
  });
}

uint64_t cacheHits(const CacheStats& s) { return s.hits + s.merged; }

// A per-ray quantity of the sampled blocks, per stratum; head and tail as their counted total.
struct Quantity {
  double fixed = 0;
  std::vector<std::vector<double>> strata;  // per stratum, per block
};

double mean(const std::vector<double>& values) {
  double sum = 0;
  for (double v : values) sum += v;
  return values.empty() ? 0 : sum / static_cast<double>(values.size());
}

// What the blocks measured, the golden model's mean cost per ray of each block and of each
// stratum as a whole (known for every ray), and the rays of each stratum.
struct Sample {
  Quantity cycles, l1Hits, l1Accesses, l2Hits, l2Accesses;
  std::vector<std::vector<double>> blockCost;
  std::vector<double> stratumCost, rays;

  // The regression estimate of q's frame total (Cochran, Sampling Techniques, 7.9): each block's
  // value adjusted by b (X_h - x) for its stratum's mean cost X_h and its own x, b the slope of
  // value on cost pooled within strata; the cost is cheap for every ray, and says how much of a
  // block's cycles come from its rays being costlier than its stratum's.
  double total(const Quantity& q) const {
    double sxy = 0, sxx = 0;
    for (size_t h = 0; h < rays.size(); ++h) {
      const double mx = mean(blockCost[h]), my = mean(q.strata[h]);
      for (size_t j = 0; j < blockCost[h].size(); ++j) {
        sxy += (blockCost[h][j] - mx) * (q.strata[h][j] - my);
        sxx += (blockCost[h][j] - mx) * (blockCost[h][j] - mx);
      }
    }
    const double slope = sxx > 0 ? sxy / sxx : 0.0;
    double total = q.fixed;
    for (size_t h = 0; h < rays.size(); ++h)
      total += rays[h] * (mean(q.strata[h]) + slope * (stratumCost[h] - mean(blockCost[h])));
    return total;
  }

  // The paired jackknife's replicate h (JK2): stratum h's second block replaced by its first.
  Sample replicate(size_t h) const {
    Sample copy = *this;
    for (Quantity* q :
         {&copy.cycles, &copy.l1Hits, &copy.l1Accesses, &copy.l2Hits, &copy.l2Accesses})
      q->strata[h][1] = q->strata[h][0];
    copy.blockCost[h][1] = copy.blockCost[h][0];
    return copy;
  }

  // An estimate and its 95 % interval: the variance is the sum over strata of the squared
  // changes of the replicates, which takes in the slope's own error and strata of unequal spread.
  template <class Estimate>
  Interval interval(const Estimate& estimate) const {
    const double value = estimate(*this);
    double variance = 0;
    for (size_t h = 0; h < rays.size(); ++h) {
      const double change = estimate(replicate(h)) - value;
      variance += change * change;
    }
    const double half = studentT975(static_cast<int>(rays.size()) - 1) * std::sqrt(variance);
    return {value, value - half, value + half};
  }
};

double meanCost(const std::vector<CoreKindResult>& golden, uint64_t first, uint64_t count) {
  double sum = 0;
  for (uint64_t i = first; i < first + count; ++i)
    sum += static_cast<double>(resultCost(golden[i]));
  return count == 0 ? 0 : sum / static_cast<double>(count);
}

Interval rateInterval(const Sample& sample, Quantity Sample::*hits, Quantity Sample::*accesses) {
  Interval rate = sample.interval([&](const Sample& s) {
    const double all = s.total(s.*accesses);
    return all > 0 ? s.total(s.*hits) / all : 0.0;
  });
  rate.low = std::max(0.0, rate.low);
  rate.high = std::min(1.0, rate.high);
  return rate;
}

}  // namespace

double studentT975(int degrees) {
  const double z = 1.959963984540054, n = std::max(1, degrees);
  const double z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z;
  return z + (z3 + z) / (4 * n) + (5 * z5 + 16 * z3 + 3 * z) / (96 * n * n) +
         (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * n * n * n);
}

uint64_t SamplePlan::blockCost() const { return warmupRays + blockRays + cooldownRays; }

uint64_t SamplePlan::simulatedRays() const {
  uint64_t total = blockRays + cooldownRays + warmupRays + blockRays;  // head, tail
  for (const Stratum& stratum : strata) total += stratum.blocks.size() * blockCost();
  return total;
}

SamplePlan planSample(uint64_t rays, int cores, const SampleSpec& spec) {
  if (!(spec.fraction > 0 && spec.fraction <= 1))
    throw std::invalid_argument("sample.fraction must be in (0, 1], got " +
                                shortText(spec.fraction));
  const double budget = spec.fraction * static_cast<double>(rays);
  SamplePlan plan;
  plan.rays = rays;
  plan.warmupRays = spec.warmupRays > 0 ? spec.warmupRays : defaultWarmupRays(cores);
  plan.cooldownRays = 2 * static_cast<uint64_t>(cores) + 16;
  plan.blockRays = spec.blockRays > 0 ? spec.blockRays
                                      : autoBlockRays(budget, plan.warmupRays, plan.cooldownRays);
  const uint64_t block = plan.blockRays;
  const double cost = static_cast<double>(plan.blockCost());
  const double ends = static_cast<double>(2 * block + plan.cooldownRays + plan.warmupRays);
  const double affordable = std::floor((budget - ends) / (2 * cost));
  const uint64_t middle = rays > 2 * block ? rays - 2 * block : 0;
  const uint64_t strata = std::min<uint64_t>(affordable > 0 ? static_cast<uint64_t>(affordable) : 0,
                                             middle / (2 * block));
  if (strata < 2) tooFew(rays, spec, block, plan.warmupRays);
  std::mt19937_64 random(spec.seed);
  for (uint64_t h = 0; h < strata; ++h) {
    SamplePlan::Stratum stratum;
    stratum.first = block + h * middle / strata;
    stratum.rays = block + (h + 1) * middle / strata - stratum.first;
    const uint64_t slots = stratum.rays / block;
    const uint64_t a = random() % slots;
    uint64_t b = random() % (slots - 1);
    if (b >= a) ++b;
    stratum.blocks = {stratum.first + a * block, stratum.first + b * block};
    plan.strata.push_back(stratum);
  }
  plan.tailFirst = rays - block;
  return plan;
}

SampledRun runSampled(const WordMemory& memory, const std::vector<HostRecord>& jobs,
                      const RtuConfig& config, const SampleSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  SampledRun run;
  run.plan = planSample(jobs.size(), config.cores, spec);
  const SamplePlan& plan = run.plan;
  const uint64_t block = plan.blockRays;

  Sample sample;
  const auto count = [&](const Block& b, bool fixed, size_t stratum) {
    const CacheStats l1 = b.counted.allL1();
    // per ray of the window: the strata weigh them by their rays
    const double values[] = {b.cycles / b.rays, static_cast<double>(cacheHits(l1)) / b.rays,
                             static_cast<double>(l1.accesses) / b.rays,
                             static_cast<double>(cacheHits(b.counted.l2.cache)) / b.rays,
                             static_cast<double>(b.counted.l2.cache.accesses) / b.rays};
    Quantity* quantities[] = {&sample.cycles, &sample.l1Hits, &sample.l1Accesses, &sample.l2Hits,
                              &sample.l2Accesses};
    for (size_t i = 0; i < 5; ++i) {
      if (fixed)
        quantities[i]->fixed += static_cast<double>(block) * values[i];
      else
        quantities[i]->strata[stratum].push_back(values[i]);
    }
    addStatistics(run.counted, b.counted);
  };
  for (Quantity* q :
       {&sample.cycles, &sample.l1Hits, &sample.l1Accesses, &sample.l2Hits, &sample.l2Accesses})
    q->strata.resize(plan.strata.size());

  // Blocks in frame order, so that one warmer walks the frame once.
  struct Place {
    uint64_t first;
    size_t stratum;  // kFixed: head or tail
  };
  constexpr size_t kFixed = SIZE_MAX;
  std::vector<Place> places{{0, kFixed}, {plan.tailFirst, kFixed}};
  for (size_t h = 0; h < plan.strata.size(); ++h)
    for (uint64_t first : plan.strata[h].blocks) places.push_back({first, h});
  std::sort(places.begin(), places.end(),
            [](const Place& a, const Place& b) { return a.first < b.first; });
  const WarmUp warmUp = config.memory.ideal ? WarmUp() : makeWarmUp(memory, jobs, config);
  for (const Place& place : places) {
    const uint64_t warmup = place.first == 0 ? 0 : plan.warmupRays;
    BlockRun options;
    if (warmUp) options.startCaches = warmUp(place.first - std::min(warmup, place.first));
    const Block measured =
        simulateBlock(memory, jobs, config, place.first, block, warmup, plan.cooldownRays, options);
    count(measured, place.stratum == kFixed, place.stratum == kFixed ? 0 : place.stratum);
  }

  const std::vector<CoreKindResult> golden = traceGolden(memory, jobs, config);
  for (const SamplePlan::Stratum& stratum : plan.strata) {
    sample.rays.push_back(static_cast<double>(stratum.rays));
    sample.stratumCost.push_back(meanCost(golden, stratum.first, stratum.rays));
    sample.blockCost.emplace_back();
    for (uint64_t first : stratum.blocks)
      sample.blockCost.back().push_back(meanCost(golden, first, block));
  }
  run.totalCycles = sample.interval([](const Sample& s) { return s.total(s.cycles); });
  if (!config.memory.ideal) {
    run.l1HitRate = rateInterval(sample, &Sample::l1Hits, &Sample::l1Accesses);
    run.l2HitRate = rateInterval(sample, &Sample::l2Hits, &Sample::l2Accesses);
  }
  run.hostSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

const StatisticGroup<SampledRun>& SampledRun::declaration() {
  using R = SampledRun;
  const auto interval = [](const Interval& i, double scale) {
    return std::vector<double>{i.low / scale, i.high / scale};
  };
  const auto rays = [](const R& r) { return static_cast<double>(r.plan.rays); };
  static const StatisticGroup<SampledRun> group =
      StatisticGroup<SampledRun>("a sampled run")
          .derived(Statistic("fraction_simulated", "",
                             "share of the frame's rays simulated, warm-ups included"),
                   [rays](const R& r) {
                     return static_cast<double>(r.plan.simulatedRays()) / rays(r);
                   })
          .derived(Statistic("simulated_rays", "rays", "rays simulated"),
                   [](const R& r) { return r.plan.simulatedRays(); })
          .derived(Statistic("block_rays", "rays", "rays counted per block"),
                   [](const R& r) { return r.plan.blockRays; })
          .derived(Statistic("warmup_rays", "rays",
                             "rays simulated before each block, not counted"),
                   [](const R& r) { return r.plan.warmupRays; })
          .derived(Statistic("strata", "", "strata of the frame, two blocks each"),
                   [](const R& r) { return r.plan.strata.size(); })
          .derived(Statistic("blocks", "", "blocks simulated: two per stratum, head and tail"),
                   [](const R& r) { return 2 * r.plan.strata.size() + 2; })
          .derived(Statistic("counted_rays", "rays", "rays of the counted blocks"),
                   [](const R& r) { return r.counted.rays; })
          .derived(Statistic("counted_cycles", "cycles", "cycles of the counted blocks"),
                   [](const R& r) { return r.counted.totalCycles; })
          .derived(Statistic("total_cycles_ci95", "cycles",
                             "95 % interval of the frame's total cycles"),
                   [interval](const R& r) { return interval(r.totalCycles, 1.0); })
          .derived(Statistic("cycles_per_ray_ci95", "cycles",
                             "95 % interval of the cycles per ray"),
                   [interval, rays](const R& r) { return interval(r.totalCycles, rays(r)); })
          .derived(Statistic("l1_hit_rate_ci95", "",
                             "95 % interval of the L1 hit rate (cached memory)"),
                   [interval](const R& r) { return interval(r.l1HitRate, 1.0); })
          .writtenWhen([](const R& r) { return !r.counted.idealMemory; })
          .derived(Statistic("l2_hit_rate_ci95", "",
                             "95 % interval of the L2 hit rate (cached memory)"),
                   [interval](const R& r) { return interval(r.l2HitRate, 1.0); })
          .writtenWhen([](const R& r) { return !r.counted.idealMemory; });
  return group;
}

nlohmann::ordered_json sampledStatisticsJson(const SampledRun& run) {
  using Json = nlohmann::ordered_json;
  RtuStatistics frame = run.counted;
  frame.rays = run.plan.rays;
  frame.totalCycles = static_cast<uint64_t>(std::llround(run.totalCycles.estimate));
  frame.hostSeconds = run.hostSeconds;
  const Json frameJson = frame.toJson();
  Json json = run.counted.toJson();
  for (const char* key :
       {"rays", "total_cycles", "cycles_per_ray", "frame_ms", "fps", "rays_per_second"})
    json[key] = frameJson[key];
  const double rays = static_cast<double>(run.plan.rays);
  if (json["memory"]["kind"] == "cached") {
    json["memory"]["l1"]["hit_rate"] = run.l1HitRate.estimate;
    json["memory"]["l2"]["hit_rate"] = run.l2HitRate.estimate;
    json["memory"]["dram"]["bytes"] =
        std::llround(run.counted.dramBytesPerCycle() * static_cast<double>(frame.totalCycles));
  }
  json["sample"] = statisticsJson(run);
  json["simulation"] = {{"model", "sampled"},
                        {"host_seconds", run.hostSeconds},
                        {"rays_per_host_second",
                         run.hostSeconds > 0 ? rays / run.hostSeconds : 0.0}};
  return json;
}

}  // namespace rtu
