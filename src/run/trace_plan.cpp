#include "run/trace_plan.h"

#include <cstdio>
#include <limits>
#include <map>
#include <ostream>
#include <stdexcept>
#include <string>

namespace rtu {
namespace {

// The listeners of --trace-ray's first run hear only the signals they look at, and nothing once
// they have found what they look for (src/trace/trace_listener.h): no window of every signal.
constexpr uint64_t kNeverListens = std::numeric_limits<uint64_t>::max();

// The cycle of the n-th transfer into the job manager (jobs enter in sequence order).
class JobEntry : public TraceListener {
 public:
  explicit JobEntry(uint64_t job) : job_(job) {}
  void declared(size_t signal, const std::string& scope, const TraceVariable& variable) override {
    if (!isJobManagerIn(scope)) return;
    if (variable.name == "valid") valid_ = static_cast<int64_t>(signal);
    if (variable.name == "ready") ready_ = static_cast<int64_t>(signal);
  }
  void changed(uint64_t cycle, const std::vector<TraceChange>& changes) override {
    if (validLevel_ && readyLevel_) {  // a transfer in every cycle since the last change
      if (job_ >= transfers_ && job_ < transfers_ + (cycle - since_))
        cycle_ = since_ + (job_ - transfers_);
      transfers_ += cycle - since_;
    }
    for (const TraceChange& change : changes) {
      if (static_cast<int64_t>(change.signal) == valid_) validLevel_ = change.value != 0;
      if (static_cast<int64_t>(change.signal) == ready_) readyLevel_ = change.value != 0;
    }
    since_ = cycle;
  }
  // Only the job manager's input matters, until the job has entered.
  uint64_t listensFrom() const override { return kNeverListens; }
  bool needsBefore(const std::string& scope, const TraceVariable&) const override {
    return isJobManagerIn(scope);
  }
  bool satisfiedBefore(uint64_t) const override { return cycle_ >= 0; }
  int64_t cycle() const { return cycle_; }

 private:
  static bool isJobManagerIn(const std::string& scope) {
    return scope.size() >= 15 && scope.compare(scope.size() - 15, 15, ".job_manager.in") == 0;
  }
  uint64_t job_;
  int64_t valid_ = -1, ready_ = -1, cycle_ = -1;
  bool validLevel_ = false, readyLevel_ = false;
  uint64_t since_ = 0, transfers_ = 0;
};

// The core that took job `ray`: the one whose input shows a transfer (valid and ready high) of
// that ray's id (the channels record each payload's ray id, transfer_channel.h).
class CoreOfRay : public TraceListener {
 public:
  explicit CoreOfRay(uint64_t ray) : ray_(ray) {}
  void declared(size_t signal, const std::string& scope, const TraceVariable& variable) override {
    if (!isCoreIn(scope)) return;
    const int core = std::stoi(scope.substr(std::string("rtu.core_").size()));
    if (variable.name == "valid") roles_[signal] = {core, Role::Valid};
    if (variable.name == "ready") roles_[signal] = {core, Role::Ready};
    if (variable.name == "ray") roles_[signal] = {core, Role::Ray};
  }
  void changed(uint64_t, const std::vector<TraceChange>& changes) override {
    for (const TraceChange& change : changes) {
      const auto role = roles_.find(change.signal);
      if (role == roles_.end()) continue;
      Input& input = inputs_[role->second.first];
      if (role->second.second == Role::Valid) input.valid = change.value != 0;
      if (role->second.second == Role::Ready) input.ready = change.value != 0;
      if (role->second.second == Role::Ray) input.ray = change.value;
    }
    for (const auto& [core, input] : inputs_)
      if (core_ < 0 && input.valid && input.ready && input.ray == ray_) core_ = core;
  }
  // Only the cores' inputs matter, until a core has taken the ray.
  uint64_t listensFrom() const override { return kNeverListens; }
  bool needsBefore(const std::string& scope, const TraceVariable&) const override {
    return isCoreIn(scope);
  }
  bool satisfiedBefore(uint64_t) const override { return core_ >= 0; }
  int core() const { return core_; }

 private:
  static bool isCoreIn(const std::string& scope) {
    static const std::string prefix = "rtu.core_", suffix = ".in";
    return scope.rfind(prefix, 0) == 0 && scope.size() > prefix.size() + suffix.size() &&
           scope.compare(scope.size() - suffix.size(), suffix.size(), suffix) == 0;
  }
  enum class Role { Valid, Ready, Ray };
  struct Input {
    bool valid = false, ready = false;
    uint64_t ray = ~uint64_t{0};
  };
  uint64_t ray_;
  std::map<size_t, std::pair<int, Role>> roles_;
  std::map<int, Input> inputs_;
  int core_ = -1;
};

std::string megabytes(uint64_t bytes) {
  char text[64];
  std::snprintf(text, sizeof text, "%.1f MB (%llu bytes)", static_cast<double>(bytes) / 1e6,
                static_cast<unsigned long long>(bytes));
  return text;
}

bool isFst(const std::string& path) {
  return path.size() > 4 && path.compare(path.size() - 4, 4, ".fst") == 0;
}

void refuseAbove(const std::string& what, const std::string& path, uint64_t bytes,
                 uint64_t maxBytes, const std::string& narrowing) {
  if (bytes <= maxBytes) return;
  throw std::invalid_argument(what + " " + path + " would be about " + megabytes(bytes) +
                              ", above --trace-max-mb " + std::to_string(maxBytes / 1000000) +
                              ": narrow it with " + narrowing + ", or raise --trace-max-mb");
}

}  // namespace

RayWindow rayWindow(const WordMemory& memory, const std::vector<HostRecord>& records,
                    const RtuConfig& config, uint64_t ray) {
  if (ray >= records.size())
    throw std::invalid_argument("--trace-ray " + std::to_string(ray) + ": the input has " +
                                std::to_string(records.size()) + " rays (0 to " +
                                std::to_string(records.size() - 1) + ")");
  RtuConfig plain = config;
  plain.trace.reset();
  plain.timeline = {};
  JobEntry entry(ray);
  CoreOfRay core(ray);
  const RtuRun run = simulateRtu(memory, records, plain, {}, {&entry, &core});
  for (size_t i = 0; i < run.jobIndices.size(); ++i)
    if (run.jobIndices[i] == ray && entry.cycle() >= 0)
      return {static_cast<uint64_t>(entry.cycle()), run.arrivalCycles[i] + 1, core.core()};
  throw std::logic_error("--trace-ray: the run shows no entry or result of ray " +
                         std::to_string(ray));
}

uint64_t traceFileBytes(const std::string& path, uint64_t vcdBytes) {
  return isFst(path) ? static_cast<uint64_t>(static_cast<double>(vcdBytes) / kVcdBytesPerFstByte)
                     : vcdBytes;
}

void reportTraceSizes(const TraceSizes& sizes, const std::string& tracePath,
                      const std::string& timelinePath, const TraceLimits& limits,
                      std::ostream& out) {
  if (!tracePath.empty()) {
    out << "trace size  " << tracePath << ": " << megabytes(sizes.trace)
        << (isFst(tracePath) ? " (estimated from its VCD's " + megabytes(sizes.vcd) + ")" : "")
        << "\n";
    refuseAbove("trace", tracePath, sizes.trace, limits.maxBytes,
                "--trace-scope, --trace-from/--trace-to, --trace-ray, an .fst path");
  }
  if (!timelinePath.empty()) {
    out << "timeline    " << timelinePath << ": " << megabytes(sizes.timeline) << "\n";
    refuseAbove("timeline", timelinePath, sizes.timeline, limits.maxBytes,
                "--trace-from/--trace-to or --trace-ray");
  }
}

TraceSizes measureTrace(const WordMemory& memory, const std::vector<HostRecord>& records,
                        const RtuConfig& config, const RunProgress& progress) {
  RtuConfig dry = config;
  if (dry.trace) dry.trace->countOnly = true;
  dry.timeline.countOnly = true;
  const RtuRun run = simulateRtu(memory, records, dry, progress);
  return {config.trace ? traceFileBytes(config.trace->path, run.traceBytes) : run.traceBytes,
          run.timelineBytes, run.traceBytes};
}

RtuConfig planTrace(const WordMemory& memory, const std::vector<HostRecord>& records,
                    RtuConfig config, const TraceLimits& limits, std::ostream& out,
                    const RunProgress& progress) {
  if (!config.trace && !config.timeline.wanted()) return config;
  if (limits.ray >= 0) {
    const RayWindow window = rayWindow(memory, records, config, static_cast<uint64_t>(limits.ray));
    out << "window      ray " << limits.ray << ": cycles " << window.from << " to "
        << window.to - 1;
    if (window.core >= 0) out << ", on core " << window.core;
    out << "\n";
    if (config.trace) {
      config.trace->fromCycle = window.from;
      config.trace->toCycle = window.to;
      if (window.core >= 0) config.trace->firstModule = "core_" + std::to_string(window.core);
      config.trace->markerCycle = window.to - 1;  // the ray's result at the host
    }
    config.timeline.fromCycle = window.from;
    config.timeline.toCycle = window.to;
  }
  const TraceSizes sizes = measureTrace(memory, records, config, progress);
  reportTraceSizes(sizes, config.trace ? config.trace->path : "", config.timeline.path, limits,
                   out);
  return config;
}

}  // namespace rtu
