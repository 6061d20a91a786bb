#include "kinds/svo/result_summary.h"

#include <algorithm>
#include <cstdio>

namespace rtu {

ResultSummary ResultSummary::of(const std::vector<TraversalResult>& results) {
  ResultSummary summary;
  for (const TraversalResult& result : results) summary.add(result);
  return summary;
}

void ResultSummary::add(const TraversalResult& result) {
  ++rays;
  hits += result.hit;
  stackOverflows += result.stackOverflow;
  tOverflows += result.tOverflow;
  belowResolution += result.belowResolution;
  hitsBehindOrigin += result.hit && result.tHit < 0;
  totalCost += result.cost;
  maxCost = std::max(maxCost, result.cost);
}

std::string ResultSummary::describe() const {
  char text[256];
  std::snprintf(text, sizeof text,
                "rays        %zu\n"
                "hits        %zu (%.1f %%)\n"
                "cost        mean %.2f, max %u cycles per ray (INIT to last state before OUT)\n",
                rays, hits, 100.0 * hitShare(), meanCost(), maxCost);
  std::string lines = text;
  if (stackOverflows)
    lines += "WARNING     " + std::to_string(stackOverflows) +
             " rays ran out of stack frames and were reported as misses\n";
  if (tOverflows)
    lines += "WARNING     " + std::to_string(tOverflows) +
             " rays have t-values beyond the fixed-point range: a t sum wrapped or a t-value "
             "saturated, so their results are unreliable (flag 2); give the format more integer "
             "bits or move the camera closer\n";
  if (belowResolution)
    lines += "WARNING     " + std::to_string(belowResolution) +
             " rays reached nodes narrower than a step of the format: their hits are decided by "
             "truncation and unreliable (flag 4); give the format more fraction bits\n";
  if (hitsBehindOrigin)
    lines += "WARNING     " + std::to_string(hitsBehindOrigin) +
             " hits lie behind the ray origin (t < 0): the camera is inside the volume, and the "
             "traversal reports the first voxel from where the ray line enters the root cube\n";
  return lines;
}

}  // namespace rtu
