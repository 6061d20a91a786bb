#include "trace/raypipe_timeline.h"

#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "base/output_file.h"

namespace rtu {
namespace {

class JsonEvents {
 public:
  JsonEvents(const TimelineOptions& options, uint64_t periodPs) : periodPs_(periodPs) {
    if (!options.countOnly) file_.emplace(options.path);
    put("{\"traceEvents\":[\n");
  }
  void event(const std::string& json) {
    put((first_ ? "" : ",\n") + json);
    first_ = false;
  }
  // Microseconds, exact to the picosecond.
  std::string time(uint64_t cycle) const {
    const uint64_t ps = cycle * periodPs_;
    std::string fraction = std::to_string(ps % 1000000);
    fraction.insert(0, 6 - fraction.size(), '0');
    while (!fraction.empty() && fraction.back() == '0') fraction.pop_back();
    return std::to_string(ps / 1000000) + (fraction.empty() ? "" : "." + fraction);
  }
  uint64_t finish() {
    put("\n],\"displayTimeUnit\":\"ns\"}\n");
    if (file_) file_->commit();
    return bytes_;
  }

 private:
  void put(const std::string& text) {
    bytes_ += text.size();
    if (file_) file_->stream() << text;
  }
  uint64_t periodPs_;
  std::optional<OutputFile> file_;
  uint64_t bytes_ = 0;
  bool first_ = true;
};

std::string padded(uint64_t value, size_t width) {
  std::string text = std::to_string(value);
  return std::string(width > text.size() ? width - text.size() : 0, '0') + text;
}

}  // namespace

uint64_t writeRaypipeTimeline(const RaypipeCycleRun& run, const TimelineOptions& options,
                              uint64_t periodPs, int raysInFlight) {
  if (options.fromCycle >= options.toCycle) throw std::invalid_argument("timeline window is empty");
  auto inWindow = [&](int64_t cycle) {
    return cycle >= 0 && static_cast<uint64_t>(cycle) >= options.fromCycle &&
           static_cast<uint64_t>(cycle) < options.toCycle;
  };
  JsonEvents json(options, periodPs);
  json.event(R"({"ph":"M","pid":1,"name":"process_name","args":{"name":"raypipe"}})");
  const size_t width = std::to_string(raysInFlight - 1).size();
  for (int id = 0; id < raysInFlight; ++id) {
    const std::string tid = std::to_string(id + 1);
    json.event("{\"ph\":\"M\",\"pid\":1,\"tid\":" + tid +
               ",\"name\":\"thread_name\",\"args\":{\"name\":\"ray_id " +
               padded(static_cast<uint64_t>(id), width) + "\"}}");
    json.event("{\"ph\":\"M\",\"pid\":1,\"tid\":" + tid +
               ",\"name\":\"thread_sort_index\",\"args\":{\"sort_index\":" + tid + "}}");
  }
  // The counters' steps: +1 / -1 per cycle, summed in cycle order.
  std::map<int64_t, std::pair<int64_t, int64_t>> steps;  // cycle -> (held, waiting)
  for (const RaypipeCycleResult& r : run.results) {
    ++steps[r.issueCycle].second;
    --steps[r.shaderInCycle].second;
    ++steps[r.shaderInCycle].first;
    --steps[r.exitCycle + 1].first;
    if (!inWindow(r.shaderInCycle)) continue;
    json.event("{\"ph\":\"X\",\"pid\":1,\"tid\":" + std::to_string(r.rayId + 1) +
               ",\"name\":\"pixel " + std::to_string(r.pixelId) +
               "\",\"ts\":" + json.time(static_cast<uint64_t>(r.shaderInCycle)) + ",\"dur\":" +
               json.time(static_cast<uint64_t>(r.exitCycle + 1 - r.shaderInCycle)) + "}");
  }
  int64_t held = 0, waiting = 0, heldShown = 0, waitingShown = 0;  // from 0 before the first
  for (const auto& [cycle, step] : steps) {
    held += step.first;
    waiting += step.second;
    if (!inWindow(cycle)) continue;
    const std::string ts = json.time(static_cast<uint64_t>(cycle));
    if (held != heldShown)  // a counter's event only where its value changes
      json.event("{\"ph\":\"C\",\"pid\":1,\"name\":\"ray ids held\",\"ts\":" + ts +
                 ",\"args\":{\"rays\":" + std::to_string(held) + "}}");
    if (waiting != waitingShown)
      json.event("{\"ph\":\"C\",\"pid\":1,\"name\":\"waiting for an id\",\"ts\":" + ts +
                 ",\"args\":{\"pixels\":" + std::to_string(waiting) + "}}");
    heldShown = held;
    waitingShown = waiting;
  }
  return json.finish();
}

}  // namespace rtu
