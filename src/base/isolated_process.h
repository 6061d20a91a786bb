#pragma once
// Runs code that may crash, hang or allocate without bound (a third-party file parser) in a
// forked child process under a CPU, wall-clock and memory limit, so that a malformed input
// costs an error message instead of the process.

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace rtu {

struct ProcessLimits {
  double seconds = 10;                       // wall clock; the CPU limit is the same, rounded up
  uint64_t memoryBytes = uint64_t{4} << 30;  // address space the child may add to the parent's
};

// The child died or ran out of time or memory: what() says which, e.g. "crashed (SIGSEGV)",
// "did not finish within 10 s", "needed more than 4096 MiB of memory".
struct IsolatedProcessError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Calls `work` in a forked child and returns the bytes it returned. The child inherits the
// parent's memory (no need to serialize the input), writes its answer through a pipe and exits
// without running the parent's destructors. At most `limits.memoryBytes` of answer are read.
// Throws IsolatedProcessError as described above; std::runtime_error with the message of the
// exception `work` threw, or when no process or pipe can be made.
std::string runIsolated(const std::function<std::string()>& work, const ProcessLimits& limits);

// Called first in a forked child: it is killed when `parent` (the parent's pid, read before the
// fork) dies, as when the parent is killed with SIGKILL, and exits at once if the parent died
// before the call.
void dieWithParent(int parent);

}  // namespace rtu
