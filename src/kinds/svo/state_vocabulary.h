#pragma once
// How the SVO core's states appear in traces and timelines: the trace encoding is CoreState's
// value, and kBlockedStateCode for the BLOCKED cycles a timed core spends waiting for a word.

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/svo/traversal_core.h"

namespace rtu {

constexpr uint64_t kBlockedStateCode = 7;
// The names of the codes, for the trace's enum table.
inline const std::vector<std::string> kCoreStateNames{"IDLE", "INIT", "EVAL", "NEXT",
                                                      "PUSH", "POP",  "OUT",  "BLOCKED"};

}  // namespace rtu
