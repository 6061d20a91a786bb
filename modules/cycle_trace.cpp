#include "cycle_trace.h"

#include "gtkw_save_file.h"

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

namespace rtu {
namespace {

std::vector<std::string> splitScope(const std::string& scope) {
  std::vector<std::string> parts;
  size_t start = 0;
  while (start <= scope.size()) {
    const size_t dot = scope.find('.', start);
    const size_t end = dot == std::string::npos ? scope.size() : dot;
    if (end > start) parts.push_back(scope.substr(start, end - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return parts;
}

}  // namespace

CycleTrace::CycleTrace(TraceOptions options) : options_(std::move(options)) {
  if (options_.fromCycle >= options_.toCycle)
    throw std::invalid_argument("trace window is empty: from cycle " +
                                std::to_string(options_.fromCycle) + " is not before " +
                                std::to_string(options_.toCycle));
  if (options_.flushCycles == 0)
    throw std::invalid_argument("trace flush interval must be at least one cycle");
  writer_ = openTraceWriter(options_.path);
}

bool CycleTrace::scopeKept(const std::string& scope) {
  if (options_.scopes.empty()) return true;
  scopeMatched_.resize(options_.scopes.size());
  bool kept = false;
  for (size_t i = 0; i < options_.scopes.size(); ++i) {
    const std::string& prefix = options_.scopes[i];
    if (scope.compare(0, prefix.size(), prefix) == 0 &&
        (scope.size() == prefix.size() || scope[prefix.size()] == '.'))
      kept = scopeMatched_[i] = true;
  }
  return kept;
}

void CycleTrace::checkScopesMatched() const {
  for (size_t i = 0; i < options_.scopes.size(); ++i) {
    if (i < scopeMatched_.size() && scopeMatched_[i]) continue;
    std::string existing;
    for (const std::string& scope : declaredScopes_) existing += "\n  " + scope;
    throw std::invalid_argument("trace scope '" + options_.scopes[i] +
                                "' matches no module; the scopes are:" + existing);
  }
}

int CycleTrace::declare(const std::string& scope, const std::string& name, int width,
                        std::vector<std::string> valueNames) {
  if (width < 1 || width > 64) throw std::invalid_argument("trace signal width must be 1 to 64");
  if (declared_)
    throw std::logic_error("trace signal " + scope + "." + name +
                           " declared after the first flush");
  declaredScopes_.insert(scope);
  if (!scopeKept(scope)) return kNoSignal;
  signals_.push_back(Signal{scope, {name, width, std::move(valueNames)}});
  return static_cast<int>(signals_.size() - 1);
}

void CycleTrace::record(int signal, uint64_t cycle, uint64_t value) {
  if (cycle < written_)
    throw std::logic_error("trace record for cycle " + std::to_string(cycle) +
                           " arrived after the cycles before " + std::to_string(written_) +
                           " were written");
  if (signal == kNoSignal || cycle >= options_.toCycle) return;
  if (cycle >= options_.fromCycle) {
    changes_.push_back(Change{cycle, signal, value});
    return;
  }
  Signal& s = signals_[static_cast<size_t>(signal)];
  if (!s.hasInitial || cycle >= s.initialCycle) {
    s.hasInitial = true;
    s.initialCycle = cycle;
    s.initialValue = value;
  }
}

void CycleTrace::flush(uint64_t cycle) {
  if (cycle <= written_) return;
  written_ = cycle;
  if (!declared_) writeDeclarations();
  // Stable: within a cycle the records stay in arrival order, so the last one still wins.
  std::stable_sort(changes_.begin(), changes_.end(),
                   [](const Change& a, const Change& b) { return a.cycle < b.cycle; });
  const auto byCycle = [](const Change& change, uint64_t c) { return change.cycle < c; };
  const auto end = std::lower_bound(changes_.begin(), changes_.end(), cycle, byCycle);
  auto begin = changes_.cbegin();
  if (!dumped_ && cycle > options_.fromCycle) {
    // The window's first cycle goes into the initial dump, so no time stamp appears twice.
    initialValues();
    for (; begin != end && begin->cycle == options_.fromCycle; ++begin) {
      known_[static_cast<size_t>(begin->signal)] = true;
      current_[static_cast<size_t>(begin->signal)] = begin->value;
    }
    writeInitialValues();
  }
  while (begin != end) {
    auto next = begin;
    while (next != end && next->cycle == begin->cycle) ++next;
    writeCycle(begin->cycle, begin, next);
    begin = next;
  }
  changes_.erase(changes_.begin(), end);
}

void CycleTrace::finish(uint64_t markerCycle) {
  flush(std::numeric_limits<uint64_t>::max());
  writer_->close();
  std::vector<SaveFileSignal> shown;
  for (const Signal& s : signals_)
    shown.push_back({s.scope, s.variable.name, s.variable.width, !s.variable.valueNames.empty()});
  writeSaveFile(options_.path, shown, markerCycle * options_.periodPs);
}

void CycleTrace::writeDeclarations() {
  declared_ = true;
  // Nested by scope path (std::map keeps scopes together and sorted).
  std::map<std::string, std::vector<size_t>> byScope;
  for (size_t i = 0; i < signals_.size(); ++i) byScope[signals_[i].scope].push_back(i);
  std::vector<std::string> open;
  for (const auto& [scope, members] : byScope) {
    const std::vector<std::string> path = splitScope(scope);
    size_t common = 0;
    while (common < open.size() && common < path.size() && open[common] == path[common]) ++common;
    for (size_t i = open.size(); i > common; --i) writer_->leaveScope();
    open.resize(common);
    for (size_t i = common; i < path.size(); ++i) {
      writer_->enterScope(path[i]);
      open.push_back(path[i]);
    }
    for (size_t index : members) writer_->variable(index, signals_[index].variable);
  }
  for (size_t i = open.size(); i > 0; --i) writer_->leaveScope();
  writer_->endDeclarations();
}

// The values before the window, final once the simulation has passed its first cycle.
void CycleTrace::initialValues() {
  known_.resize(signals_.size());
  current_.resize(signals_.size());
  for (size_t i = 0; i < signals_.size(); ++i) {
    known_[i] = signals_[i].hasInitial;
    current_[i] = signals_[i].initialValue;
  }
}

void CycleTrace::writeInitialValues() {
  dumped_ = true;
  writer_->beginInitial(options_.fromCycle * options_.periodPs);
  for (size_t i = 0; i < signals_.size(); ++i) writer_->value(i, known_[i], current_[i]);
  writer_->endInitial();
}

void CycleTrace::writeCycle(uint64_t cycle, std::vector<Change>::const_iterator begin,
                            std::vector<Change>::const_iterator end) {
  // The last record of a signal in this cycle is its value; emit it if it changed.
  std::map<int, uint64_t> settled;
  for (auto change = begin; change != end; ++change) settled[change->signal] = change->value;
  bool stamped = false;
  for (const auto& [signal, value] : settled) {
    const auto index = static_cast<size_t>(signal);
    if (known_[index] && current_[index] == value) continue;
    if (!stamped) writer_->time(cycle * options_.periodPs);
    stamped = true;
    known_[index] = true;
    current_[index] = value;
    writer_->value(index, true, value);
  }
}

}  // namespace rtu
