#pragma once
// One row of an exploration (fps, sweep): the configured camera's frame of primary rays on a
// scene built for the row's core kind (frame_scene.h), simulated on the cycle-accurate model, or,
// with architecture = raypipe, the ray pipe's frame on its timed model (raypipe_row.h); the row is
// the run's JSON (version, effective configuration, statistics), the same a single `render
// --stats` writes.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/index_ranges.h"
#include "config/configuration.h"
#include "explore/frame_scene.h"

namespace rtu {

// Scenes built once, each for its kind (frame_scene.h), and shared by the rows (workers fork after
// they are built).
class SceneCache {
 public:
  // Notes the scene a configuration names (configurations are added one at a time: a sweep's are
  // not held together), then build() builds every scene noted; a scene that fails keeps its error
  // for its rows.
  void need(const Configuration& configuration);
  void build();
  // Throws std::runtime_error with the build error of a scene that failed.
  const FrameScene& scene(const RunConfig& settings) const;
  // The built scenes as word files with an index in `directory` (for Slurm array tasks), and
  // back; errors name the directory.
  void save(const std::string& directory) const;
  void load(const std::string& directory);

 private:
  std::map<std::string, RunConfig> uses_;  // each scene's settings, with its rows' deepest stack
  std::map<std::string, FrameScene> scenes_;
  std::map<std::string, std::string> errors_;
};

// Which model answers a row: always the SystemC simulation, or the recurrence of
// src/rtu/rtu_recurrence.h where it is exact for the configuration (the same cycles and statistics,
// tests/test_rtu_recurrence.cpp) and the SystemC simulation elsewhere. A simulated row with
// sample.fraction > 0 simulates a sample of the frame (sampled_run.h) and estimates the rest.
enum class RowModel { Simulation, RecurrenceWhereExact };

// The run JSON with "status": "ok" and the architecture's "resources" (architecture_resources.h);
// throws for an impossible configuration or a stalled run.
nlohmann::ordered_json runFrameRow(const Configuration& configuration, const FrameScene& scene,
                                   RowModel model = RowModel::Simulation);
// runFrameRow, or the failed row of a configuration that cannot run.
nlohmann::ordered_json runRowSafely(const Configuration& configuration, const SceneCache& scenes,
                                    RowModel model = RowModel::Simulation);

// Throws std::invalid_argument when the configuration cannot run whatever the scene: its camera,
// its RTU (rtu/validate) or a sample on a model other than the cycle-accurate one; for the ray
// pipe, validateRaypipeRow.
void validateRow(const Configuration& configuration);
bool isValidRow(const Configuration& configuration);
// The configurations of an exploration's rows, computed on demand from the row's index (a sweep's
// points are not held together).
using ConfigurationAt = std::function<Configuration(size_t)>;

// The row of a configuration that failed ("invalid": validateRow refused it, it is not run again
// on resume; "failed": its run failed, it runs again on resume) or whose worker died ("lost": it
// may run another time), with the error.
nlohmann::ordered_json failedRow(const Configuration& configuration, const std::string& error,
                                 const std::string& status = "failed");

// Runs configuration(i) for each i in `rows` in up to `workers` worker processes, after
// validating them (an invalid one goes to `done` at once as an "invalid" row with its error, and is
// not run) and building their scenes once, with progress on standard error; `done(i, row)` gets
// each row as it finishes (a failed configuration gives a failed row, a dead worker a lost one).
// Holds the rows in flight, not `rows`. Returns the rows that are not "ok".
size_t runRows(const ConfigurationAt& configuration, const IndexRanges& rows, int workers,
               const std::string& label,
               const std::function<void(size_t, const nlohmann::ordered_json&)>& done,
               RowModel model = RowModel::Simulation);

// The statistics columns of the CSV outputs: rays,total_cycles,cycles_per_ray,frame_ms,fps,limit
// first, then hit rates, core time shares, scheduler waits, DRAM traffic, the model, and for
// sampled rows the 95 % interval of total_cycles and the fraction of rays simulated.
const std::vector<std::string>& statisticsColumns();
// Each column with the key of the statistic it holds ("cost/mean"; an interval's end as
// "sample/total_cycles_ci95/0").
const std::vector<std::pair<std::string, std::string>>& statisticsColumnKeys();
// A row's values for those columns (empty strings for a failed row).
std::vector<std::string> statisticsValues(const nlohmann::ordered_json& row);
// A value as a CSV field: a string as it is, a float in %.10g, anything else as JSON.
std::string csvValue(const nlohmann::ordered_json& value);
// One CSV line (RFC 4180 quoting) with its newline.
std::string csvLine(const std::vector<std::string>& fields);

}  // namespace rtu
