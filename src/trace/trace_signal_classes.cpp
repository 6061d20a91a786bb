#include "trace/trace_signal_classes.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace rtu {

const std::vector<std::string>& traceSignalClasses() {
  static const std::vector<std::string> classes{"handshakes", "ids",    "states",
                                                "stack",      "caches", "fifos"};
  return classes;
}

std::string traceSignalClass(const std::string& name) {
  static const std::map<std::string, std::string> byName{
      {"valid", "handshakes"},
      {"ready", "handshakes"},
      {"ray", "ids"},
      {"state", "states"},
      {"stack_depth", "stack"},
      {"hits", "caches"},
      {"misses", "caches"},
      // the ray pipe's (sim/raypipe/pipe_trace.h)
      {"stall", "handshakes"},
      {"pixel", "ids"},
      {"count", "fifos"}};
  const auto found = byName.find(name);
  return found == byName.end() ? "" : found->second;
}

void checkTraceSignalClasses(const std::vector<std::string>& classes) {
  const std::vector<std::string>& known = traceSignalClasses();
  for (const std::string& name : classes) {
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    throw std::invalid_argument("trace signal class '" + name +
                                "' does not exist; the classes are " + list);
  }
}

}  // namespace rtu
