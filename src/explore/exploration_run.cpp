#include "explore/exploration_run.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "base/binary_file.h"
#include "base/input_file.h"
#include "base/output_file.h"
#include "config/run_json.h"
#include "explore/architecture_resources.h"
#include "explore/ray_passes.h"
#include "explore/raypipe_frame.h"
#include "explore/raypipe_row.h"
#include "explore/sweep_workers.h"
#include "run/analytic_run.h"
#include "run/rtu_simulation.h"
#include "run/sampled_run.h"
#include "run/statistics_output.h"
#include "run/statistics_window.h"

namespace rtu {
namespace {

// A row's work for the progress line's ETA: the rays of its frame.
double rowRays(const Configuration& configuration) {
  const RunConfig& settings = configuration.values();
  if (settings.architecture == Architecture::Raypipe) {
    const PrgFrameSize size = raypipeFrameSize(settings);
    return static_cast<double>(size.width) * static_cast<double>(size.height);
  }
  return static_cast<double>(settings.camera.width) * static_cast<double>(settings.camera.height);
}

}  // namespace

void SceneCache::need(const Configuration& configuration) {
  // An octree too deep for every stack that will run it is refused before it is built (a deep
  // procedural scene takes minutes and gigabytes): it is built with the deepest stack of its rows;
  // each row still checks its own (frameRecords).
  const RunConfig& settings = configuration.values();
  auto [use, added] = uses_.emplace(frameSceneKey(settings), settings);
  int& stackFrames = use->second.rtu.coreConfig<SvoKind>().stackFrames;
  stackFrames = std::max(stackFrames, settings.rtu.coreConfig<SvoKind>().stackFrames);
  use->second.allowStackOverflow |= settings.allowStackOverflow;
}

void SceneCache::build() {
  for (const auto& [key, use] : uses_) {
    if (scenes_.count(key) || errors_.count(key)) continue;
    try {
      scenes_.emplace(key, loadFrameScene(use));
    } catch (const std::exception& error) {
      errors_.emplace(key, error.what());
    }
  }
}

const FrameScene& SceneCache::scene(const RunConfig& settings) const {
  const std::string key = frameSceneKey(settings);
  const auto error = errors_.find(key);
  if (error != errors_.end()) throw std::runtime_error("scene: " + error->second);
  return scenes_.at(key);
}

void SceneCache::save(const std::string& directory) const {
  nlohmann::json index = nlohmann::json::object();
  size_t number = 0;
  for (const auto& [key, scene] : scenes_) {
    const std::string file = "scene_" + std::to_string(number++) + ".words";
    writeWordFile(directory + "/" + file, scene.words);
    index[key] = {{"file", file},
                  {"core", scene.core},
                  {"entry", scene.entry},
                  {"name", scene.name},
                  {"description", scene.description},
                  {"stack_needed", scene.stackNeeded}};
  }
  for (const auto& [key, error] : errors_) index[key] = {{"error", error}};
  writeTextFile(directory + "/scenes.json", index.dump(2) + "\n");
}

void SceneCache::load(const std::string& directory) {
  const nlohmann::json index = nlohmann::json::parse(
      readInputFile(directory + "/scenes.json", "sweep scene index", kMaxSettingsFileBytes));
  for (const auto& [key, entry] : index.items()) {
    if (entry.contains("error")) {
      errors_[key] = entry["error"].get<std::string>();
      continue;
    }
    FrameScene scene;
    scene.words = readWordFile(directory + "/" + entry["file"].get<std::string>(), sizeof(uint32_t),
                               "scene image");
    scene.core = entry["core"].get<std::string>();
    scene.entry = entry["entry"].get<uint32_t>();
    scene.name = entry["name"].get<std::string>();
    scene.description = entry["description"].get<std::string>();
    scene.stackNeeded = entry["stack_needed"].get<int>();
    scenes_[key] = std::move(scene);
  }
}

namespace {

// A row of secondary passes (workload.rays beyond primary) spawns them from its kind's golden
// hits of the camera's frame and times them on a timed model, every ray.
void validatePasses(const RunConfig& settings) {
  if (parseRayPasses(settings.rayPasses, "workload.rays").size() < 2) return;
  const std::string passes = "workload.rays " + settings.rayPasses + ": ";
  if (recordedWorkload(settings))
    throw std::invalid_argument(passes +
                                "secondary passes need the camera's frame, not recorded rays");
  if (settings.model == ModelKind::Golden)
    throw std::invalid_argument(passes + "a row's passes need a timed model (ca or lt)");
  if (settings.sample.enabled())
    throw std::invalid_argument(passes + "--sample samples primary frames only");
}

nlohmann::ordered_json passJson(const RtuStatistics& s) { return statisticsJson(FramePass{s}); }

// The row of a frame with secondary passes: its statistics are the frame's, the one run of the
// primary rays and every pass's as one job stream (fps is the whole frame's rate), and
// statistics.passes holds each pass's own figures, its window of that run (the primary's the run
// of its rays alone), which sum to the frame's.
nlohmann::ordered_json framePassesRow(const Configuration& configuration, const FrameScene& scene,
                                      const RtuStatistics& primary) {
  const RunConfig& settings = configuration.values();
  const std::vector<RayType> passes = parseRayPasses(settings.rayPasses, "workload.rays");
  const FramePassesRun frame = runFramePasses(scene, settings, passes, primary);
  nlohmann::ordered_json each = {{"primary", passJson(primary)}};
  for (const PassRun& pass : frame.passes) each[toString(pass.type)] = passJson(*pass.statistics);
  nlohmann::ordered_json row = {{"status", "ok"}, {"error", ""}};
  row.update(runJson(*frame.frame, configuration));
  row["statistics"]["passes"] = each;
  return row;
}

nlohmann::ordered_json okRow(const Configuration& configuration, const FrameScene& scene,
                             const RtuStatistics& statistics) {
  if (parseRayPasses(configuration.values().rayPasses, "workload.rays").size() > 1)
    return framePassesRow(configuration, scene, statistics);
  nlohmann::ordered_json row = {{"status", "ok"}, {"error", ""}};
  row.update(runJson(statistics, configuration));
  return row;
}

}  // namespace

void validateRow(const Configuration& configuration) {
  const RunConfig& settings = configuration.values();
  if (settings.architecture == Architecture::Raypipe) return validateRaypipeRow(settings);
  settings.camera.validate();
  validate(settings.rtu);
  if (settings.model != ModelKind::CycleAccurate && settings.sample.enabled())
    throw std::invalid_argument(std::string("--sample samples the cycle-accurate model: it does "
                                            "not go with --model ") +
                                toString(settings.model));
  validatePasses(settings);
}

bool isValidRow(const Configuration& configuration) {
  try {
    validateRow(configuration);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

namespace {

nlohmann::ordered_json frameRow(const Configuration& configuration, const FrameScene& scene,
                                RowModel model) {
  const RunConfig& settings = configuration.values();
  if (settings.architecture == Architecture::Raypipe) return runRaypipeRow(configuration, scene);
  validateRow(configuration);
  const std::vector<HostRecord> records = frameRecords(scene, settings);
  const WordMemory memory = scene.memory();
  if (settings.model != ModelKind::CycleAccurate)
    return okRow(configuration, scene,
                 runModel(settings.model, memory, records, settings.rtu).statistics);
  const bool recurrence = model == RowModel::RecurrenceWhereExact && !whyNotAnalytic(settings.rtu);
  if (!recurrence && settings.sample.enabled()) {
    nlohmann::ordered_json row = {{"status", "ok"}, {"error", ""}};
    row.update(runJson(RtuStatistics{}, configuration));
    row["statistics"] =
        sampledStatisticsJson(runSampled(memory, records, settings.rtu, settings.sample));
    return row;
  }
  const RtuRun run = recurrence ? runAnalytic(memory, records, settings.rtu)
                                : simulateRtu(memory, records, settings.rtu);
  return okRow(configuration, scene, run.statistics);
}

}  // namespace

nlohmann::ordered_json runFrameRow(const Configuration& configuration, const FrameScene& scene,
                                   RowModel model) {
  nlohmann::ordered_json row = frameRow(configuration, scene, model);
  row["resources"] =
      resourcesJson(architectureResources(configuration.values(), scene.words.size()));
  return row;
}

nlohmann::ordered_json runRowSafely(const Configuration& configuration, const SceneCache& scenes,
                                    RowModel model) {
  try {
    return runFrameRow(configuration, scenes.scene(configuration.values()), model);
  } catch (const std::exception& error) {
    return failedRow(configuration, error.what());
  }
}

nlohmann::ordered_json failedRow(const Configuration& configuration, const std::string& error,
                                 const std::string& status) {
  return {{"status", status},
          {"error", error},
          {"rtusim", {{"version", rtusimVersion()}}},
          {"preset", configuration.preset()},
          {"config", configuration.toJson()}};
}

size_t runRows(const ConfigurationAt& configuration, const IndexRanges& rows, int workers,
               const std::string& label,
               const std::function<void(size_t, const nlohmann::ordered_json&)>& done,
               RowModel model) {
  size_t finished = 0, failures = 0;
  SceneCache scenes;
  double rays = 0, raysDone = 0;  // the ETA weighs rows by rays: 1920x1080 is 36 times 320x180
  rows.forEach([&](size_t row) {
    const Configuration settings = configuration(row);
    try {
      validateRow(settings);
      scenes.need(settings);
      rays += rowRays(settings);
    } catch (const std::invalid_argument& error) {
      ++finished;
      ++failures;
      done(row, failedRow(settings, error.what(), "invalid"));
    }
  });
  scenes.build();
  Progress progress(label, rows.count());
  IndexRanges::Cursor cursor(rows);
  const NextRow nextValid = [&](size_t& row) {  // the invalid rows are done
    while (cursor.next(row))
      if (isValidRow(configuration(row))) return true;
    return false;
  };
  const auto work = [&](size_t row) {
    return runRowSafely(configuration(row), scenes, model).dump();
  };
  runInWorkers(nextValid, workers, work, [&](size_t row, const WorkerOutcome& outcome) {
    const Configuration settings = configuration(row);
    nlohmann::ordered_json result;
    try {
      result = outcome.answered ? nlohmann::ordered_json::parse(outcome.line)
                                : failedRow(settings, outcome.failure, "lost");
    } catch (const nlohmann::json::exception& error) {
      result = failedRow(settings, std::string("unreadable worker answer: ") + error.what());
    }
    failures += result["status"] != "ok";
    done(row, result);
    raysDone += rowRays(settings);
    progress.update(++finished, failures, raysDone / rays);
  });
  progress.finish();
  return failures;
}

namespace {

using Json = nlohmann::ordered_json;

// Where each column's value is in the statistics JSON.
const std::vector<std::pair<std::string, Json::json_pointer>>& columnPointers() {
  static const std::vector<std::pair<std::string, Json::json_pointer>> columns = [] {
    std::vector<std::pair<std::string, Json::json_pointer>> all;
    for (const auto& [name, key] : statisticsColumnKeys())
      all.emplace_back(name, Json::json_pointer("/" + key));
    return all;
  }();
  return columns;
}

// The columns every row has, whatever its kind.
std::vector<std::pair<std::string, std::string>> generalColumnKeys() {
  return {{"rays", "rays"},
          {"total_cycles", "total_cycles"},
          {"cycles_per_ray", "cycles_per_ray"},
          {"frame_ms", "frame_ms"},
          {"fps", "fps"},
          {"limit", "limit"},
          {"limit_utilisation", "limit_utilisation"},
          {"util_cores", "utilisation/cores"},
          {"util_memory_latency", "utilisation/memory_latency"},
          {"util_dram_bandwidth", "utilisation/dram_bandwidth"},
          {"util_l2_port", "utilisation/l2_port"},
          {"util_host_in", "utilisation/host_in"},
          {"util_host_out", "utilisation/host_out"},
          {"util_job_manager", "utilisation/job_manager"},
          {"cost_mean", "cost/mean"},
          {"blocked_mean", "blocked_cycles/mean"},
          {"core_busy", "core_time/busy"},
          {"core_blocked", "core_time/blocked"},
          {"core_handover", "core_time/handover"},
          {"core_idle", "core_time/idle"},
          {"core_unit_stall", "core_time/triangle_unit_stall"},
          {"max_wait", "scheduler/max_wait"},
          {"l1_hit_rate", "memory/l1/hit_rate"},
          {"l2_hit_rate", "memory/l2/hit_rate"},
          {"dram_bytes", "memory/dram/bytes"},
          {"dram_bytes_per_cycle", "memory/dram/bytes_per_cycle"},
          {"host_seconds", "simulation/host_seconds"},
          {"answered_by", "simulation/model"},
          {"total_cycles_ci_low", "sample/total_cycles_ci95/0"},
          {"total_cycles_ci_high", "sample/total_cycles_ci95/1"},
          {"simulated_fraction", "sample/fraction_simulated"}};
}

// Each pass's rays and cycles per ray (workload.rays; empty for a pass the row does not run).
std::vector<std::pair<std::string, std::string>> passColumnKeys() {
  std::vector<std::pair<std::string, std::string>> columns;
  for (const char* pass : {"primary", "shadow", "ao", "reflection", "diffuse", "random"})
    for (const char* figure : {"rays", "cycles_per_ray"})
      columns.emplace_back(std::string(pass) + "_" + figure,
                           std::string("passes/") + pass + "/" + figure);
  return columns;
}

}  // namespace

std::string csvValue(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) {
    char text[64];
    std::snprintf(text, sizeof text, "%.10g", value.get<double>());
    return text;
  }
  return value.dump();
}

const std::vector<std::pair<std::string, std::string>>& statisticsColumnKeys() {
  static const std::vector<std::pair<std::string, std::string>> columns = [] {
    std::vector<std::pair<std::string, std::string>> all = generalColumnKeys();
    for (const auto& column : passColumnKeys()) all.push_back(column);
    // Every kind's counters (run totals; zero for a kind the row does not run), as named in the
    // statistics JSON.
    for (const Statistic& counter : CoreKinds::Counters::declaration().statistics())
      all.emplace_back(counter.key, counter.key);
    return all;
  }();
  return columns;
}

const std::vector<std::string>& statisticsColumns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const auto& [name, pointer] : columnPointers()) all.push_back(name);
    return all;
  }();
  return names;
}

std::vector<std::string> statisticsValues(const Json& row) {
  std::vector<std::string> values;
  const bool ok = row.contains("statistics");
  for (const auto& [name, pointer] : columnPointers()) {
    const Json* statistics = ok ? &row["statistics"] : nullptr;
    values.push_back(statistics && statistics->contains(pointer) ? csvValue((*statistics)[pointer])
                                                                 : "");
  }
  return values;
}

std::string csvLine(const std::vector<std::string>& fields) {
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    const std::string& field = fields[i];
    if (field.find_first_of(",\"\n") == std::string::npos) {
      line += field;
      continue;
    }
    line += '"';
    for (char c : field) line += c == '"' ? std::string("\"\"") : std::string(1, c);
    line += '"';
  }
  return line + "\n";
}

}  // namespace rtu
