#pragma once
// Maps the pages of a vector's reserved capacity in one call rather than a page fault each as
// they are first written: a 1280x720 run's buffers of results and records are tens of MB. Linux
// 5.14 on; elsewhere, or should the call fail, the pages still come one fault at a time.

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <vector>

namespace rtu {

template <class T>
void prefaultCapacity(const std::vector<T>& vector) {
#ifdef MADV_POPULATE_WRITE
  if (vector.capacity() == 0) return;
  const auto page = static_cast<uintptr_t>(sysconf(_SC_PAGESIZE));
  const auto data = reinterpret_cast<uintptr_t>(vector.data());
  const uintptr_t begin = data & ~(page - 1);
  const uintptr_t end = data + vector.capacity() * sizeof(T);
  madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)vector;
#endif
}

}  // namespace rtu
