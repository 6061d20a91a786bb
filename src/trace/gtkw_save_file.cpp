#include "trace/gtkw_save_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <tuple>

#include "base/output_file.h"
#include "raypipe/raypipe_run.h"
#include "trace/trace_writer.h"

namespace rtu {
namespace {

// GTKWave's display flags (gtkwave analyzer.h): right-justified binary or decimal values, the
// names of the trace's enum table (TR_ENUM, bit 32) or of a translate filter file
// (TR_FTRANSLATED, bit 13) over binary, as GTKWave itself saves them, and the comment lines that
// open and close a group.
constexpr const char* kBinary = "@28";
constexpr const char* kDecimal = "@24";
constexpr const char* kEnum = "@100000028";
constexpr const char* kTranslated = "@2028";
constexpr const char* kGroupBegin = "@800200";
constexpr const char* kGroupEnd = "@1000200";

// The module: the scope's second part (rtu.core_3.in -> core_3).
std::string moduleOf(const std::string& scope) {
  const size_t first = scope.find('.');
  if (first == std::string::npos) return scope;
  const size_t second = scope.find('.', first + 1);
  const size_t length = second == std::string::npos ? std::string::npos : second - first - 1;
  return scope.substr(first + 1, length);
}

// The ray pipe's modules (sim/raypipe/pipe_trace.h): its units in the pipe's order, then its
// FIFOs.
int raypipePosition(const std::string& module) {
  for (size_t u = 0; u < static_cast<size_t>(RaypipeUnit::kCount); ++u)
    if (module == raypipeUnitName(static_cast<RaypipeUnit>(u))) return static_cast<int>(u);
  return static_cast<int>(RaypipeUnit::kCount);
}

// Pipeline position of a module, then its instance number (core_10 after core_9); `first` before
// all.
std::tuple<int, long, std::string> pipelineKey(const std::string& scope, const std::string& first) {
  const std::string module = moduleOf(scope);
  if (module == first) return {-1, 0, module};
  if (scope.rfind("raypipe.", 0) == 0) return {raypipePosition(module), 0, module};
  static const std::vector<std::string> order{"job_manager", "scheduler",      "core_",
                                              "memory",      "result_manager", "reorder_buffer"};
  for (size_t i = 0; i < order.size(); ++i)
    if (module.rfind(order[i], 0) == 0) {
      const std::string suffix = module.substr(order[i].size());
      const bool numbered = !suffix.empty() && std::all_of(suffix.begin(), suffix.end(), ::isdigit);
      return {static_cast<int>(i), numbered ? std::stol(suffix) : 0, module};
    }
  return {static_cast<int>(order.size()), 0, module};
}

std::string displayName(const SaveFileSignal& signal) {
  const std::string name = signal.scope + "." + signal.name;
  return signal.width == 1 ? name : name + "[" + std::to_string(signal.width - 1) + ":0]";
}

// What the signal is called inside its module's group: the scope below the module and the name,
// apart by spaces ("in valid" for rtu.core_03.in.valid). GTKWave shows a name up to its last
// dot only (hier_max_level), so twenty rows of "valid" and "ready" without an alias.
std::string alias(const SaveFileSignal& signal) {
  std::string path = signal.scope + "." + signal.name;
  for (int dots = 0; dots < 2 && !path.empty();) {  // drop "rtu." and the module
    const size_t dot = path.find('.');
    if (dot == std::string::npos) break;
    path.erase(0, dot + 1);
    ++dots;
  }
  std::replace(path.begin(), path.end(), '.', ' ');
  return path;
}

bool isFst(const std::string& tracePath) {
  return std::filesystem::path(tracePath).extension() == ".fst";
}

// A GTKWave translate filter for a VCD signal's named values ("010 EVAL"), next to the trace:
// t.vcd's core states go to t.state.txt. Returns its absolute path.
std::string writeTranslateFilter(const std::string& tracePath, const SaveFileSignal& signal) {
  std::filesystem::path path(tracePath);
  path.replace_extension("." + signal.name + ".txt");
  OutputFile file(path.string());
  for (size_t value = 0; value < signal.valueNames.size(); ++value)
    file.stream() << bitString(value, signal.width) << ' ' << signal.valueNames[value] << '\n';
  file.commit();
  return std::filesystem::absolute(path).string();
}

}  // namespace

std::string saveFilePath(const std::string& tracePath) { return tracePath + ".gtkw"; }

// GTKWave (3.3.x) shows 2^-zoom times this many time units across the waves of a window of the
// save file's [size], measured: gtkwave -S with getWindowStartTime/getWindowEndTime under xvfb
// (docs/waveforms.md).
constexpr double kUnitsAtZoomZero = 4.3;

double zoomToFit(uint64_t span) {
  const double shown = static_cast<double>(std::max<uint64_t>(span, 1)) * 1.05;
  return std::log2(kUnitsAtZoomZero / shown);
}

void writeSaveFile(const std::string& tracePath, const std::vector<SaveFileSignal>& signals,
                   const SaveFileView& view, const std::string& firstModule) {
  const std::string path = saveFilePath(tracePath);
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << "[dumpfile] \"" << std::filesystem::absolute(tracePath).string() << "\"\n";
  out << "[size] 1400 900\n[timestart] " << view.start << '\n';
  char zoom[32];
  std::snprintf(zoom, sizeof zoom, "*%.6f ", zoomToFit(view.end - view.start));
  out << zoom << view.marker;
  for (int i = 0; i < 26; ++i) out << " -1";           // no named markers
  out << "\n[sst_expanded] 1\n[signals_width] 240\n";  // room for "stack_depth =BLOCKED"

  std::map<std::tuple<int, long, std::string>, std::vector<const SaveFileSignal*>> byModule;
  std::map<std::string, std::string> translateFilters;  // by signal name, for a VCD
  // Signals of the top scope itself (the clock) come first, outside the groups.
  for (const SaveFileSignal& signal : signals)
    if (signal.scope.find('.') == std::string::npos)
      out << kBinary << "\n+{" << signal.name << "} " << displayName(signal) << '\n';
  for (const SaveFileSignal& signal : signals) {
    if (signal.scope.find('.') == std::string::npos) continue;
    byModule[pipelineKey(signal.scope, firstModule)].push_back(&signal);
    if (!signal.valueNames.empty() && !isFst(tracePath) && !translateFilters.count(signal.name))
      translateFilters[signal.name] = writeTranslateFilter(tracePath, signal);
  }
  for (const auto& [key, members] : byModule) {
    const std::string& module = std::get<2>(key);
    out << kGroupBegin << "\n-" << module << '\n';
    for (const SaveFileSignal* signal : members) {
      if (signal->valueNames.empty())
        out << (signal->width == 1 ? kBinary : kDecimal) << '\n';
      else if (isFst(tracePath))
        out << kEnum << '\n';
      else
        out << kTranslated << "\n^1 " << translateFilters[signal->name] << '\n';
      out << "+{" << alias(*signal) << "} " << displayName(*signal) << '\n';
    }
    out << kGroupEnd << "\n-" << module << '\n';
  }
  file.commit();
}

}  // namespace rtu
