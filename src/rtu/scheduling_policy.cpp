#include "rtu/scheduling_policy.h"

#include <stdexcept>

namespace rtu {

SchedulerPolicy parseSchedulerPolicy(const std::string& name) {
  if (name == "cfa") return SchedulerPolicy::CyclicFirstAvailable;
  if (name == "rr") return SchedulerPolicy::RoundRobin;
  if (name == "fa") return SchedulerPolicy::FirstAvailable;
  throw std::invalid_argument("unknown scheduler '" + name +
                              "': choose cfa (cyclic first-available), rr (round-robin) or fa "
                              "(first-available)");
}

const char* toString(SchedulerPolicy policy) {
  switch (policy) {
    case SchedulerPolicy::CyclicFirstAvailable: return "cfa";
    case SchedulerPolicy::RoundRobin: return "rr";
    case SchedulerPolicy::FirstAvailable: return "fa";
  }
  return "?";
}

}  // namespace rtu
