#pragma once
// How much memory this machine has, for the checks that refuse a model or a tree that would not
// fit before any long work starts (docs/robustness.md).

#include <cstdint>
#include <string>

namespace rtu {

uint64_t physicalMemoryBytes();

std::string formatGiB(double bytes);  // "8.9 GiB"

}  // namespace rtu
