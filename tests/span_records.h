#pragma once
// Span rays for the kinds' tests (rtu/ray_span.h): a frame's primary ray records (unit
// directions, tests/kind_fixture.h) moved kIntoModel units along, so that they start inside the
// cube [-1, 1]^3 the fixtures' scenes fill (the default camera stands some 3.4 units from its
// centre), each with the span `spanOf(i)` gives.

#include <cstddef>
#include <variant>
#include <vector>

#include "kinds/registry.h"

namespace rtu {

constexpr float kIntoModel = 2.5f;

template <class SpanOf>
std::vector<HostRecord> movedIntoModel(const std::vector<HostRecord>& primaries, SpanOf spanOf) {
  std::vector<HostRecord> records;
  for (size_t i = 0; i < primaries.size(); ++i) {
    RayRecord record = std::get<RayRecord>(primaries[i]);
    for (int k = 0; k < 3; ++k) record.origin[k] += kIntoModel * record.direction[k];
    record.span = spanOf(i);
    records.emplace_back(record);
  }
  return records;
}

// Every record with the one span.
inline std::vector<HostRecord> movedIntoModel(const std::vector<HostRecord>& primaries,
                                              RaySpan span) {
  return movedIntoModel(primaries, [span](size_t) { return span; });
}

}  // namespace rtu
