#pragma once
// `golden --accel-file` on a triangle kind's image (app/kind_image_file.h): the ray records traced
// by the kind's golden model in the image's own space, as `replay --core <kind> --model golden`
// traces them (app/triangle_replay.h: an identity model header after the image, every record
// naming model address 0), under the run's settings of the kind; their CSV rows and golden's
// report (rays, hits, mean cost, nodes and triangle tests per ray, host time).

#include <chrono>
#include <string>
#include <vector>

#include "app/golden_summary.h"
#include "app/kind_image_file.h"
#include "app/triangle_replay.h"
#include "kinds/core_result.h"
#include "run/analytic_run.h"

namespace rtu {

template <class Kind>
std::string traceImageGolden(const RunConfig& settings, const std::vector<RayRecord>& rays,
                             std::vector<ResultRow>& rows) {
  const TriangleReplayInput input =
      triangleReplayInput(Kind::kName, settings.accel.file, rays, settings.rays);
  RtuConfig config = settings.rtu;
  config.core = Kind::kName;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<CoreKindResult> results =
      traceGolden(WordMemory(input.words), input.records, config);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rows = KindImageFile<Kind>::rows(results, input.words);
  uint64_t cost = 0, nodes = 0, triangleTests = 0;
  for (const auto& result : resultsOfKind<Kind>(results)) {
    cost += result.cost;
    nodes += result.counts.nodes;
    triangleTests += result.counts.triangleTests;
  }
  return triangleGoldenSummary(rows, cost, nodes, triangleTests, seconds);
}

}  // namespace rtu
