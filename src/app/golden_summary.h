#pragma once
// The report of `golden` on a triangle image (app/kind_image_file.h): rays, hits, mean cost and
// the nodes and triangle tests per ray, and the host's time.

#include <cstdint>
#include <string>
#include <vector>

#include "app/results_csv.h"

namespace rtu {

std::string triangleGoldenSummary(const std::vector<ResultRow>& rows, uint64_t cost, uint64_t nodes,
                                  uint64_t triangleTests, double seconds);

}  // namespace rtu
