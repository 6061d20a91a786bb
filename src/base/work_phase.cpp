#include "base/work_phase.h"

#include <exception>
#include <utility>

namespace rtu {

namespace {
thread_local std::string current;
}

WorkPhase::WorkPhase(std::string what) : previous_(std::exchange(current, std::move(what))) {}

// A phase left by an exception stays current: the catch that reports it runs after the unwinding.
// Where the exception is caught and the work goes on, the stale phase lasts only until the next
// phase begins or the enclosing one ends.
WorkPhase::~WorkPhase() {
  if (std::uncaught_exceptions() == 0) current = std::move(previous_);
}

const std::string& currentWorkPhase() { return current; }

}  // namespace rtu
