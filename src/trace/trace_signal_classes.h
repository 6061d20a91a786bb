#pragma once
// The classes of traced signals a trace can be narrowed to (--trace-signals), by signal name:
// handshakes (valid, ready), ids (ray: the ray each channel's payload belongs to), states (core
// state), stack (stack_depth), caches (hits, misses).

#include <string>
#include <vector>

namespace rtu {

const std::vector<std::string>& traceSignalClasses();

// The class of a signal named `name`; empty for a name of no class.
std::string traceSignalClass(const std::string& name);

// Throws std::invalid_argument, listing the classes, for a name that is none of them.
void checkTraceSignalClasses(const std::vector<std::string>& classes);

}  // namespace rtu
