#pragma once
// Aggregate figures over a set of traversal results: what every report prints.

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/svo/thesis_records.h"

namespace rtu {

struct ResultSummary {
  size_t rays = 0;
  size_t hits = 0;
  size_t stackOverflows = 0;
  size_t tOverflows = 0;
  size_t belowResolution = 0;
  size_t hitsBehindOrigin = 0;  // hits at t < 0: the camera is inside the root cube
  uint64_t totalCost = 0;
  uint32_t maxCost = 0;

  static ResultSummary of(const std::vector<TraversalResult>& results);
  // Counts one more result (a frame's results summed as they leave a run).
  void add(const TraversalResult& result);
  double meanCost() const { return rays ? static_cast<double>(totalCost) / rays : 0.0; }
  double hitShare() const { return rays ? static_cast<double>(hits) / rays : 0.0; }
  std::string describe() const;  // a few report lines
};

}  // namespace rtu
