#include "trace/timeline_writer.h"

#include <algorithm>
#include <stdexcept>

namespace rtu {
namespace {

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// "core_12" -> 12; npos for another name.
size_t coreIndex(const std::string& name) {
  const std::string prefix = "core_";
  if (!startsWith(name, prefix) || name.size() == prefix.size()) return std::string::npos;
  const std::string digits = name.substr(prefix.size());
  if (digits.find_first_not_of("0123456789") != std::string::npos) return std::string::npos;
  return std::stoul(digits);
}

// The scope below the top (rtu.core_3.in -> core_3.in).
std::string belowTop(const std::string& scope) {
  const size_t dot = scope.find('.');
  return dot == std::string::npos ? "" : scope.substr(dot + 1);
}

// The channels whose transfers the counters count: job manager in, scheduler in, the cores'
// outputs, result manager out, reorder buffer out.
bool counted(const std::string& key) {
  return key == "job_manager.in" || key == "scheduler.in" || key == "result_manager.out" ||
         key == "reorder_buffer.out" || (startsWith(key, "core_") && endsWith(key, ".out"));
}

}  // namespace

TimelineWriter::TimelineWriter(TimelineOptions options, uint64_t periodPs, StateVocabulary states)
    : options_(std::move(options)), periodPs_(periodPs), states_(std::move(states)) {
  if (options_.fromCycle >= options_.toCycle)
    throw std::invalid_argument("timeline window is empty");
  if (options_.countOnly) return;
  file_.emplace(options_.path);
}

void TimelineWriter::declared(size_t signal, const std::string& scope,
                              const TraceVariable& variable) {
  if (roles_.size() <= signal) roles_.resize(signal + 1);
  const std::string key = belowTop(scope);
  const size_t core = coreIndex(key);
  const size_t coreIn = endsWith(key, ".in") ? coreIndex(key.substr(0, key.size() - 3))
                                             : std::string::npos;
  if (core != std::string::npos && variable.name == "state") {
    if (cores_.size() <= core) cores_.resize(core + 1, Core{states_.idle});
    roles_[signal] = {Role::CoreState, core};
  } else if (coreIn != std::string::npos && variable.name == "ray") {
    if (cores_.size() <= coreIn) cores_.resize(coreIn + 1, Core{states_.idle});
    roles_[signal] = {Role::CoreRay, coreIn};
  } else if (variable.name == "valid" || variable.name == "ready") {
    roles_[signal] = {variable.name == "valid" ? Role::Valid : Role::Ready, channel(key)};
  }
}

size_t TimelineWriter::channel(const std::string& key) {
  for (size_t i = 0; i < channels_.size(); ++i)
    if (channels_[i].key == key) return i;
  channels_.push_back(Channel{key});
  return channels_.size() - 1;
}

bool TimelineWriter::needsBefore(const std::string& scope, const TraceVariable& variable) const {
  return (variable.name == "valid" || variable.name == "ready") && counted(belowTop(scope));
}

void TimelineWriter::changed(uint64_t cycle, const std::vector<TraceChange>& changes) {
  if (!started_) writeHeader();
  advanceTo(cycle);
  apply(cycle, changes);
  findStreaming();
  sampleCounters(cycle);
}

// The levels before the window: a core busy there runs a ray that started before it (not shown).
void TimelineWriter::held(uint64_t, const std::vector<TraceChange>& values) {
  if (!started_) writeHeader();
  for (const TraceChange& value : values) {
    const SignalRole& role = roles_[value.signal];
    if (role.role == Role::CoreState)
      cores_[role.index].state = value.value;
    else
      level(role, value.value);
  }
  findStreaming();
}

// A core's state first, then the ray its input carries: a core leaving IDLE runs the ray its
// input carried in the cycles before (the handshake's).
void TimelineWriter::apply(uint64_t cycle, const std::vector<TraceChange>& changes) {
  for (const TraceChange& change : changes) {
    const SignalRole& role = roles_[change.signal];
    if (role.role == Role::CoreState) coreState(role.index, cycle, change.value);
    if (role.role == Role::Valid || role.role == Role::Ready) level(role, change.value);
  }
  for (const TraceChange& change : changes)
    if (roles_[change.signal].role == Role::CoreRay) level(roles_[change.signal], change.value);
}

void TimelineWriter::level(const SignalRole& role, uint64_t value) {
  if (role.role == Role::Valid) channels_[role.index].valid = value != 0;
  if (role.role == Role::Ready) channels_[role.index].ready = value != 0;
  if (role.role == Role::CoreRay) cores_[role.index].offered = value;
}

void TimelineWriter::findStreaming() {
  streaming_.clear();
  for (size_t i = 0; i < channels_.size(); ++i)
    if (channels_[i].valid && channels_[i].ready) streaming_.push_back(i);
}

// Past the window, with every ray that started in it handed over.
bool TimelineWriter::satisfiedBefore(uint64_t cycle) const {
  if (cycle < options_.toCycle) return false;
  return std::none_of(cores_.begin(), cores_.end(),
                      [&](const Core& c) { return c.state != states_.idle && inWindow(c.start); });
}

// Counts the transfers of the cycles from the cursor up to `cycle` (levels held since the last
// change), and samples the counters after each.
void TimelineWriter::advanceTo(uint64_t cycle) {
  if (streaming_.empty()) cursor_ = cycle;
  for (; cursor_ < cycle; ++cursor_) {
    for (size_t i : streaming_) transfer(channels_[i]);
    sampleCounters(cursor_ + 1);
  }
}

void TimelineWriter::coreState(size_t core, uint64_t cycle, uint64_t state) {
  Core& c = cores_[core];
  if (c.state == states_.blocked)
    slice(core, states_.names[states_.blocked], c.blockedStart, cycle);
  if (state != states_.idle && c.state == states_.idle) {
    c.ray = c.offered;
    c.start = cycle;
  }
  if (state == states_.blocked) c.blockedStart = cycle;
  if (state == states_.out) c.outStart = cycle;
  if (state == states_.idle && c.state == states_.out) {
    slice(core, states_.names[states_.out], c.outStart, cycle);
    slice(core, "ray " + std::to_string(c.ray), c.start, cycle);
  }
  c.state = state;
}

// A complete event; nested slices come before their ray's (the viewers sort by time).
void TimelineWriter::slice(size_t core, const std::string& name, uint64_t from, uint64_t to) {
  if (!inWindow(cores_[core].start)) return;
  event("{\"ph\":\"X\",\"pid\":1,\"tid\":" + std::to_string(core + 1) + ",\"name\":\"" + name +
        "\",\"ts\":" + time(from) + ",\"dur\":" + time(to - from) + "}");
}

void TimelineWriter::sampleCounters(uint64_t cycle) {
  if (!inWindow(cycle)) return;
  if (waitChannel_ != kNone) {
    const Channel& in = channels_[waitChannel_];
    counters_[kWaitCounter].held = in.valid && !in.ready;
  }
  for (Counter& counter : counters_) {
    if (counter.written == counter.held) continue;
    counter.written = counter.held;
    event("{\"ph\":\"C\",\"pid\":1,\"name\":\"" + counter.name + "\",\"ts\":" + time(cycle) +
          ",\"args\":{\"" + counter.unit + "\":" + std::to_string(counter.held) + "}}");
  }
}

void TimelineWriter::transfer(const Channel& channel) {
  if (channel.into != kNone) ++counters_[channel.into].held;
  if (channel.outOf != kNone) --counters_[channel.outOf].held;
}

// The counters: what each channel's transfers add to or take from them.
void TimelineWriter::assignCounters() {
  counters_ = {
      {"job manager", "jobs"}, {"scheduler wait", "pending"}, {"result manager", "results"}};
  for (size_t i = 0; i < channels_.size(); ++i) {
    Channel& c = channels_[i];
    if (c.key == "job_manager.in") c.into = kJobCounter;
    if (c.key == "scheduler.in") c.outOf = kJobCounter, waitChannel_ = i;
    if (startsWith(c.key, "core_") && endsWith(c.key, ".out")) c.into = kResultCounter;
    if (c.key == "result_manager.out") c.outOf = kResultCounter;
    if (c.key == "reorder_buffer.out") {
      counters_.push_back({"reorder buffer", "results"});
      c.outOf = kReorderCounter;
    }
  }
  for (Channel& c : channels_)
    if (c.key == "result_manager.out" && counters_.size() > kReorderCounter)
      c.into = kReorderCounter;
}

// Track names, zero-padded to sort in order (core_03), and the counters this run has.
void TimelineWriter::writeHeader() {
  started_ = true;
  const size_t width = std::to_string(cores_.empty() ? 0 : cores_.size() - 1).size();
  const std::string begin = "{\"traceEvents\":[\n";
  bytes_ += begin.size();
  if (!options_.countOnly) file_->stream() << begin;
  event(R"({"ph":"M","pid":1,"name":"process_name","args":{"name":"rtu"}})");
  for (size_t i = 0; i < cores_.size(); ++i) {
    std::string index = std::to_string(i);
    index.insert(0, width - index.size(), '0');
    const std::string tid = std::to_string(i + 1);
    event("{\"ph\":\"M\",\"pid\":1,\"tid\":" + tid +
          ",\"name\":\"thread_name\",\"args\":{\"name\":\"core_" + index + "\"}}");
    event("{\"ph\":\"M\",\"pid\":1,\"tid\":" + tid +
          ",\"name\":\"thread_sort_index\",\"args\":{\"sort_index\":" + tid + "}}");
  }
  assignCounters();
}

void TimelineWriter::event(const std::string& json) {
  const std::string line = (firstEvent_ ? "" : ",\n") + json;
  firstEvent_ = false;
  bytes_ += line.size();
  if (!options_.countOnly) file_->stream() << line;
}

bool TimelineWriter::inWindow(uint64_t cycle) const {
  return cycle >= options_.fromCycle && cycle < options_.toCycle;
}

// Microseconds, exact to the picosecond.
std::string TimelineWriter::time(uint64_t cycle) const {
  const uint64_t ps = cycle * periodPs_;
  std::string fraction = std::to_string(ps % 1000000);
  fraction.insert(0, 6 - fraction.size(), '0');
  while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
  return std::to_string(ps / 1000000) + (fraction.empty() ? "" : "." + fraction);
}

void TimelineWriter::finished() {
  if (!started_) writeHeader();
  const std::string end = "\n],\"displayTimeUnit\":\"ns\"}\n";
  bytes_ += end.size();
  if (options_.countOnly) return;
  file_->stream() << end;
  file_->commit();
}

}  // namespace rtu
