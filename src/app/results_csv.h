#pragma once
// Results as CSV (issue 27, `--results-csv FILE`): one row per ray, `id,hit,t,primitive,u,v`, t
// along the ray record's direction in its units (world units for a unit direction), the
// primitive and barycentrics of a triangle hit (empty for the SVO kind, whose hits are voxels),
// every field empty but id and hit on a miss. Numbers in their shortest exact form.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rtu {

struct ResultRow {
  uint32_t id = 0;
  bool hit = false;
  double t = 0;
  std::optional<uint32_t> primitive;
  std::optional<double> u, v;
};

// Throws std::runtime_error naming `path` when it cannot be written.
void writeResultsCsv(const std::string& path, const std::vector<ResultRow>& rows);

}  // namespace rtu
