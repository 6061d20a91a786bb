#pragma once
// What the program is doing, for the one message that cannot say it where it happens: an
// allocation that fails (std::bad_alloc carries no words). The outermost catch names the phase
// that was current when it was thrown (issue 33: "out of memory while reading SVO image 'f.svo'
// (6 GiB)" instead of a bare std::bad_alloc).

#include <string>

namespace rtu {

// Marks a phase for its lifetime; phases nest, the innermost is current. Not for hot loops: it
// copies its text.
class WorkPhase {
 public:
  explicit WorkPhase(std::string what);
  ~WorkPhase();
  WorkPhase(const WorkPhase&) = delete;
  WorkPhase& operator=(const WorkPhase&) = delete;

 private:
  std::string previous_;
};

// The innermost phase of this thread, or "" outside every phase.
const std::string& currentWorkPhase();

}  // namespace rtu
