#pragma once
// The speed-accuracy trade, measured on one frame and configuration: each faster way of answering
// (golden, the recurrence where it applies, the loosely-timed model at several quanta, sampled
// simulation at several fractions) against the
// cycle-accurate SystemC model, which answers every ray. `rtusim fidelity` prints it;
// docs/fidelity.md holds the measured tables.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "run/rtu_simulation.h"
#include "run/sampled_run.h"

namespace rtu {

struct ModeFidelity {
  std::string mode;  // "systemc", "recurrence", "lt q1000", "sampled 0.1", "golden"
  double hostSeconds = 0;
  double raysPerHostSecond = 0;
  double speedUp = 1;  // over the SystemC model's host seconds
  // Frame cycles and their error relative to SystemC's; absent for golden (untimed).
  std::optional<double> totalCycles, totalCyclesError;
  std::optional<Interval> totalCyclesInterval;  // sampled
  // Per ray: |cycles - SystemC's cycles| / SystemC's, cycles = cost + blocked; absent when the
  // mode has no cycles per ray (sampled). Golden's are its cost: memory stalls are not in it.
  std::optional<double> perRayErrorMean, perRayErrorP99;
  // Cache hit rates and their difference from SystemC's in percentage points (cached memory).
  std::optional<double> l1HitRate, l2HitRate, l1Error, l2Error;
  // Per-ray results (hit, t, normal, flags, cost) equal the golden model's; absent: not known.
  std::optional<bool> resultsEqualGolden;
};

// Mean and 99th percentile of |mode - reference| / reference over the rays (0 where the
// reference is 0).
std::pair<double, double> perRayErrors(const std::vector<double>& mode,
                                       const std::vector<double>& reference);

// The modes in order: systemc, recurrence (where it applies), lt per quantum, sampled per
// fraction (with `sample` for seed and block sizes), golden: of the kind config.core, whose
// records `jobs` are.
std::vector<ModeFidelity> measureFidelity(const WordMemory& memory,
                                          const std::vector<HostRecord>& jobs,
                                          const RtuConfig& config,
                                          const std::vector<uint64_t>& quanta,
                                          const std::vector<double>& fractions, SampleSpec sample);

}  // namespace rtu
