#include "rtu/host_memory.h"

#include <unistd.h>

#include <cstdio>

namespace rtu {

uint64_t physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0) return UINT64_MAX;  // unknown: no limit from here
  return static_cast<uint64_t>(pages) * static_cast<uint64_t>(pageSize);
}

std::string formatGiB(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return text;
}

}  // namespace rtu
