#include "trace/cycle_trace.h"

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>

#include "trace/gtkw_save_file.h"
#include "trace/instance_names.h"
#include "trace/trace_signal_classes.h"

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

CycleTrace::CycleTrace(TraceOptions options, std::vector<TraceListener*> listeners)
    : options_(std::move(options)), listeners_(std::move(listeners)) {
  if (options_.fromCycle >= options_.toCycle)
    throw std::invalid_argument("trace window is empty: from cycle " +
                                std::to_string(options_.fromCycle) + " is not before " +
                                std::to_string(options_.toCycle));
  if (options_.flushCycles == 0)
    throw std::invalid_argument("trace flush interval must be at least one cycle");
  if (options_.clock && options_.periodPs < 2)
    throw std::invalid_argument("a traced clock needs a clock period of at least 2 ps (at most "
                                "500,000 MHz)");
  checkTraceSignalClasses(options_.signalClasses);
  chooseTimeUnit();
  listening_ = !listeners_.empty();
  if (listening_) {
    listenFrom_ = std::numeric_limits<uint64_t>::max();
    for (TraceListener* listener : listeners_)
      listenFrom_ = std::min(listenFrom_, listener->listensFrom());
    heldTold_ = listenFrom_ == 0;
  }
  if (options_.countOnly)
    writer_ = openVcdCounter(counter_, unit_);
  else if (!options_.path.empty())
    writer_ = openTraceWriter(options_.path, unit_);
}

void CycleTrace::chooseTimeUnit() {
  const std::optional<TraceTimeUnit> period = TraceTimeUnit::ofPicoseconds(options_.periodPs);
  if (options_.time == TraceTime::Cycles && options_.clock)
    throw std::invalid_argument("a trace in cycles (--trace-time cycles) cannot show a traced "
                                "clock (--trace-clock), whose falling edges are in mid-cycle: "
                                "trace in picoseconds (--trace-time ps)");
  if (options_.time == TraceTime::Cycles && !period)
    throw std::invalid_argument(
        "a trace in cycles (--trace-time cycles) needs a clock period of a power of ten "
        "picoseconds, as VCD and FST timescales are (10 ns at 100 MHz); this clock's is " +
        std::to_string(options_.periodPs) + " ps: trace in picoseconds (--trace-time ps)");
  const bool cycles = options_.time == TraceTime::Cycles ||
                      (options_.time == TraceTime::Auto && period && !options_.clock);
  unit_ = cycles ? *period : TraceTimeUnit{};
  ticksPerCycle_ = cycles ? 1 : options_.periodPs;
}

bool CycleTrace::scopeKept(const std::string& scope) {
  if (options_.scopes.empty()) return true;
  scopeMatched_.resize(options_.scopes.size());
  bool kept = false;
  const std::string plain = unpaddedScope(scope);
  for (size_t i = 0; i < options_.scopes.size(); ++i) {
    const std::string prefix = unpaddedScope(options_.scopes[i]);
    if (plain.compare(0, prefix.size(), prefix) == 0 &&
        (plain.size() == prefix.size() || plain[prefix.size()] == '.'))
      kept = scopeMatched_[i] = true;
  }
  return kept;
}

bool CycleTrace::classKept(const std::string& name) const {
  const std::vector<std::string>& classes = options_.signalClasses;
  return classes.empty() ||
         std::find(classes.begin(), classes.end(), traceSignalClass(name)) != classes.end();
}

void CycleTrace::checkScopesMatched() const {
  for (size_t i = 0; i < options_.scopes.size(); ++i) {
    if (i < scopeMatched_.size() && scopeMatched_[i]) continue;
    InstanceWidths widths;
    for (const std::string& scope : declaredScopes_) widths.add(scope);
    std::string existing;
    for (const std::string& scope : declaredScopes_) existing += "\n  " + widths.padded(scope);
    throw std::invalid_argument("trace scope '" + options_.scopes[i] +
                                "' matches no module; the scopes are:" + existing);
  }
  if (writer_ && signals_.empty()) {
    std::string scopes, classes;
    for (const std::string& scope : options_.scopes) scopes += " " + scope;
    for (const std::string& signalClass : options_.signalClasses) classes += " " + signalClass;
    throw std::invalid_argument("the trace would hold no signal: the scopes" + scopes +
                                " have none of the signal classes" + classes);
  }
}

int CycleTrace::declare(const std::string& scope, const std::string& name, int width,
                        std::vector<std::string> valueNames) {
  if (width < 1 || width > 64) throw std::invalid_argument("trace signal width must be 1 to 64");
  if (declared_)
    throw std::logic_error("trace signal " + scope + "." + name +
                           " declared after the first flush");
  declaredScopes_.insert(scope);
  const bool kept = scopeKept(scope) && classKept(name) && writer_;
  if (!kept && listeners_.empty()) return kNoSignal;
  TraceVariable variable{name, width, std::move(valueNames)};
  bool early = listenFrom_ == 0;
  for (TraceListener* listener : listeners_) {
    listener->declared(fileIndex_.size(), scope, variable);
    early = early || listener->needsBefore(scope, variable);
  }
  early_.push_back(early);
  fileIndex_.push_back(kept ? static_cast<int>(signals_.size()) : kNoSignal);
  if (kept) signals_.push_back(Signal{scope, std::move(variable)});
  return static_cast<int>(fileIndex_.size() - 1);
}

void CycleTrace::record(int signal, uint64_t cycle, uint64_t value) {
  if (cycle < written_)
    throw std::logic_error("trace record for cycle " + std::to_string(cycle) +
                           " arrived after the cycles before " + std::to_string(written_) +
                           " were written");
  if (signal == kNoSignal) return;
  const auto id = static_cast<size_t>(signal);
  const int index = fileIndex_[id];
  const bool forFile =
      index != kNoSignal && cycle >= options_.fromCycle && cycle < options_.toCycle;
  const bool heldForListeners = listening_ && cycle < listenFrom_ && !early_[id];
  if (heldForListeners) {
    if (heldFor_.size() <= id) heldFor_.resize(fileIndex_.size());
    hold(heldFor_[id], cycle, value);
  }
  if (forFile || (listening_ && !heldForListeners)) {
    changes_.push_back(Change{cycle, signal, value});
    return;
  }
  // Before a window only the value it starts from matters: kept in place, not queued, so the
  // cycles before a window cost little more than untraced ones.
  if (index != kNoSignal && cycle < options_.fromCycle)
    hold(signals_[static_cast<size_t>(index)].initial, cycle, value);
}

// The latest record before the window wins; within a cycle the last to arrive.
void CycleTrace::hold(Held& held, uint64_t cycle, uint64_t value) {
  if (held.known && cycle < held.cycle) return;
  held = {true, cycle, value};
}

void CycleTrace::flush(uint64_t cycle) {
  if (cycle <= written_) return;
  written_ = cycle;
  if (!declared_) writeDeclarations();
  sortPending();
  const auto byCycle = [](const Change& change, uint64_t c) { return change.cycle < c; };
  const auto end = std::lower_bound(changes_.begin(), changes_.end(), cycle, byCycle);
  for (auto begin = changes_.cbegin(); begin != end;) {
    auto next = begin;
    while (next != end && next->cycle == begin->cycle) ++next;
    settle(begin, next);
    if (!heldTold_ && begin->cycle >= listenFrom_) tellHeld();
    notifyListeners(begin->cycle, settled_);
    if (writer_) fileCycle(begin->cycle, settled_);
    begin = next;
  }
  changes_.erase(changes_.begin(), end);
  sorted_ = changes_.size();
  if (!heldTold_ && cycle >= listenFrom_) tellHeld();
  checkListenersSatisfied();
  if (writer_ && !dumped_ && cycle > options_.fromCycle) {
    initialValues();
    writeInitialValues();
  }
}

void CycleTrace::finish(uint64_t firstResult) {
  flush(std::numeric_limits<uint64_t>::max());
  for (TraceListener* listener : listeners_) listener->finished();
  if (!writer_) return;
  writer_->close();
  if (options_.countOnly) return;
  std::vector<SaveFileSignal> shown;
  for (const Signal& s : signals_)
    shown.push_back({s.scope, s.variable.name, s.variable.width, s.variable.valueNames});
  const uint64_t first = options_.fromCycle;
  const uint64_t last = std::max(first, std::min(lastFiled_, options_.toCycle - 1));
  uint64_t marker = options_.markerCycle.value_or(firstResult);
  if (marker < first || marker > last) marker = first;
  const uint64_t factor = unit_.viewerFactor();
  writeSaveFile(options_.path, shown,
                {timeOf(marker) * factor, timeOf(first) * factor, timeOf(last + 1) * factor},
                options_.firstModule);
}

void CycleTrace::writeDeclarations() {
  declared_ = true;
  if (!writer_) return;
  InstanceWidths widths;
  for (const std::string& scope : declaredScopes_) widths.add(scope);
  for (Signal& signal : signals_) signal.scope = widths.padded(signal.scope);
  if (options_.clock) declareClock();
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

// The clock lives in the top scope of the traced modules (rtu.clk), whatever the scope filter.
void CycleTrace::declareClock() {
  const std::string& first = signals_.empty() ? std::string("rtu") : signals_.front().scope;
  clockIndex_ = signals_.size();
  signals_.push_back(Signal{first.substr(0, first.find('.')), TraceVariable{"clk", 1, {}}});
}

void CycleTrace::clockUpTo(uint64_t end) {
  for (; clockNext_ < end; ++clockNext_) {
    writer_->time(timeOf(clockNext_));
    writer_->value(clockIndex_, true, 1);
    fallingEdge(clockNext_);
  }
}

void CycleTrace::fallingEdge(uint64_t cycle) {
  writer_->time(timeOf(cycle) + ticksPerCycle_ / 2);
  writer_->value(clockIndex_, true, 0);
  current_[clockIndex_] = 0;
}

// Stable: within a cycle the records stay in arrival order, so the last one still wins. The
// records left from the last flush are in order already (modules record ahead of simulated time,
// so they can be many): only those that came since are sorted, then merged behind them.
void CycleTrace::sortPending() {
  const auto byCycle = [](const Change& a, const Change& b) { return a.cycle < b.cycle; };
  const auto middle = changes_.begin() + static_cast<std::ptrdiff_t>(sorted_);
  if (!countingSort(middle, changes_.end())) std::stable_sort(middle, changes_.end(), byCycle);
  std::inplace_merge(changes_.begin(), middle, changes_.end(), byCycle);
  sorted_ = changes_.size();
}

// A stable counting sort by cycle when the records span few cycles against their number (those
// of one flush interval do): two linear passes instead of a merge sort. False when it does not
// apply.
bool CycleTrace::countingSort(std::vector<Change>::iterator begin,
                              std::vector<Change>::iterator end) {
  const size_t count = static_cast<size_t>(end - begin);
  if (count < 2) return true;
  const auto [low, high] = std::minmax_element(begin, end, [](const Change& a, const Change& b) {
    return a.cycle < b.cycle;
  });
  const uint64_t first = low->cycle, span = high->cycle - first + 1;
  if (span > 2 * count + options_.flushCycles) return false;
  cycleStarts_.assign(span + 1, 0);
  for (auto change = begin; change != end; ++change) ++cycleStarts_[change->cycle - first + 1];
  for (size_t i = 1; i <= span; ++i) cycleStarts_[i] += cycleStarts_[i - 1];
  scratch_.resize(count);
  for (auto change = begin; change != end; ++change)
    scratch_[cycleStarts_[change->cycle - first]++] = *change;
  std::copy(scratch_.begin(), scratch_.end(), begin);
  return true;
}

// Without a map per cycle: each signal's last record is marked by its index in this round, and
// the signals found are sorted (a cycle has few).
void CycleTrace::settle(std::vector<Change>::const_iterator begin,
                        std::vector<Change>::const_iterator end) {
  lastRecord_.resize(fileIndex_.size());
  lastRecordRound_.resize(fileIndex_.size());
  ++settleRound_;
  settled_.clear();
  for (auto change = begin; change != end; ++change) {
    const auto signal = static_cast<size_t>(change->signal);
    if (lastRecordRound_[signal] != settleRound_) {
      lastRecordRound_[signal] = settleRound_;
      settled_.push_back({signal, 0});
    }
    lastRecord_[signal] = static_cast<size_t>(change - begin);
  }
  std::sort(settled_.begin(), settled_.end(),
            [](const TraceChange& a, const TraceChange& b) { return a.signal < b.signal; });
  for (TraceChange& change : settled_) change.value = begin[lastRecord_[change.signal]].value;
}

// Every cycle before the listeners' window is final: the values their late signals hold there.
void CycleTrace::tellHeld() {
  heldTold_ = true;
  heldFor_.resize(fileIndex_.size());
  heard_.resize(fileIndex_.size());
  heardValue_.resize(fileIndex_.size());
  changed_.clear();
  for (size_t signal = 0; signal < heldFor_.size(); ++signal) {
    if (!heldFor_[signal].known) continue;
    heard_[signal] = true;
    heardValue_[signal] = heldFor_[signal].value;
    changed_.push_back({signal, heldFor_[signal].value});
  }
  heldFor_ = {};
  for (TraceListener* listener : listeners_) listener->held(listenFrom_ - 1, changed_);
}

// The cycles before written_ are heard: a listener may need no more.
void CycleTrace::checkListenersSatisfied() {
  if (!listening_) return;
  for (TraceListener* listener : listeners_)
    if (!listener->satisfiedBefore(written_)) return;
  listening_ = false;
}

void CycleTrace::notifyListeners(uint64_t cycle, const Settled& settled) {
  if (!listening_) return;
  heard_.resize(fileIndex_.size());
  heardValue_.resize(fileIndex_.size());
  changed_.clear();
  for (const TraceChange& change : settled) {
    if (cycle < listenFrom_ && !early_[change.signal]) continue;  // held (tellHeld)
    if (heard_[change.signal] && heardValue_[change.signal] == change.value) continue;
    heard_[change.signal] = true;
    heardValue_[change.signal] = change.value;
    changed_.push_back(change);
  }
  if (changed_.empty()) return;
  for (TraceListener* listener : listeners_) listener->changed(cycle, changed_);
}

// Before the window a cycle only sets the values the window starts from; the window's first
// cycle goes into the initial dump, so no time stamp appears twice.
void CycleTrace::fileCycle(uint64_t cycle, const Settled& settled) {
  if (cycle >= options_.toCycle) return;
  if (cycle < options_.fromCycle) {
    for (const TraceChange& change : settled) {
      const int index = fileIndex_[change.signal];
      if (index != kNoSignal)
        hold(signals_[static_cast<size_t>(index)].initial, cycle, change.value);
    }
    return;
  }
  if (!dumped_) {
    initialValues();
    if (cycle == options_.fromCycle) {
      for (const TraceChange& change : settled) {
        const int index = fileIndex_[change.signal];
        if (index == kNoSignal) continue;
        known_[static_cast<size_t>(index)] = true;
        current_[static_cast<size_t>(index)] = change.value;
      }
      writeInitialValues();
      return;
    }
    writeInitialValues();
  }
  writeCycle(cycle, settled);
}

// The values before the window, final once the simulation has passed its first cycle.
void CycleTrace::initialValues() {
  known_.resize(signals_.size());
  current_.resize(signals_.size());
  for (size_t i = 0; i < signals_.size(); ++i) {
    known_[i] = signals_[i].initial.known;
    current_[i] = signals_[i].initial.value;
  }
}

void CycleTrace::writeInitialValues() {
  dumped_ = true;
  if (options_.clock) {
    known_[clockIndex_] = true;
    current_[clockIndex_] = 1;
  }
  writer_->beginInitial(timeOf(options_.fromCycle));
  for (size_t i = 0; i < signals_.size(); ++i) writer_->value(i, known_[i], current_[i]);
  writer_->endInitial();
  if (!options_.clock) return;
  fallingEdge(options_.fromCycle);
  clockNext_ = options_.fromCycle + 1;
}

// A signal is written when its value changed; with a clock, every cycle up to this one is.
void CycleTrace::writeCycle(uint64_t cycle, const Settled& settled) {
  lastFiled_ = cycle;
  bool stamped = false;
  if (options_.clock) {
    clockUpTo(cycle);
    writer_->time(timeOf(cycle));
    writer_->value(clockIndex_, true, 1);
    stamped = true;
  }
  for (const TraceChange& change : settled) {
    const int signal = fileIndex_[change.signal];
    if (signal == kNoSignal) continue;
    const auto index = static_cast<size_t>(signal);
    if (known_[index] && current_[index] == change.value) continue;
    if (!stamped) writer_->time(timeOf(cycle));
    stamped = true;
    known_[index] = true;
    current_[index] = change.value;
    writer_->value(index, true, change.value);
  }
  if (!options_.clock) return;
  fallingEdge(cycle);
  clockNext_ = cycle + 1;
}

}  // namespace rtu
