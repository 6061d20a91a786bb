#include "app/golden_summary.h"

#include <cstdio>

namespace rtu {

std::string triangleGoldenSummary(const std::vector<ResultRow>& rows, uint64_t cost, uint64_t nodes,
                                  uint64_t triangleTests, double seconds) {
  size_t hits = 0;
  for (const ResultRow& row : rows) hits += row.hit;
  const size_t rays = rows.size();
  const double n = rays == 0 ? 1.0 : static_cast<double>(rays);
  char text[320];
  std::snprintf(text, sizeof text,
                "rays        %zu\nhits        %zu (%.1f %%)\ncost        mean %.2f states per ray\n"
                "per ray     %.2f nodes, %.2f triangle tests\nhost        %g s\n",
                rays, hits, 100.0 * hits / n, cost / n, nodes / n, triangleTests / n, seconds);
  return text;
}

}  // namespace rtu
