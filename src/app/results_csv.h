#pragma once
// Results as CSV (issue 27, `--results-csv FILE`): one row per ray, `id,hit,t,primitive,u,v`, t
// along the ray record's direction in its units (world units for a unit direction), the
// primitive and barycentrics of a triangle hit (empty for the SVO kind, whose hits are voxels),
// every field empty but id and hit on a miss. Numbers in their shortest exact form. A writer may
// add integer columns after v (the ray pipe's pixel coordinates and counts), named once and filled
// on every row, hit or miss.

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
  std::vector<uint64_t> extra;  // the values of the extra columns, in their order
};

// Throws std::runtime_error naming `path` when it cannot be written.
// `extraColumns` names the columns of each row's `extra`.
void writeResultsCsv(const std::string& path, const std::vector<ResultRow>& rows,
                     const std::vector<std::string>& extraColumns = {});

}  // namespace rtu
