#pragma once
// A sweep as a Slurm job array. The submitting rtusim writes a sweep directory (on a file system
// the cluster's nodes share): the sweep's points (sweep_points.h: the base and grid, each point
// computed from its index) with the indices still to run as ranges, the scenes built once, and a
// batch script whose array elements each run `rtusim sweep --slurm-task ID --sweep-dir DIR` on
// every tasks-th row to run, appending rows to their own file. Nothing in it grows with the grid.
// It submits with `sbatch --wait`, shows progress from the rows written, and hands every row to the
// caller (which writes the sweep's CSV and JSON lines as a local sweep does). See docs/slurm.md.

#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "base/index_ranges.h"
#include "config/sweep_points.h"

namespace rtu {

struct SlurmOptions {
  std::string partition;  // empty: the cluster's default
  int tasks = 0;          // array elements; 0: one per configuration, at most 256
  bool dryRun = false;    // write the directory and the batch script, do not submit
};

// Runs points.at(i) for each i in `rows`. Configurations that are not valid (validateRow) go to
// `done` as invalid rows and are not submitted. Returns the path of the batch script.
std::string runRowsOnSlurm(const SweepPoints& points, const IndexRanges& rows,
                           const std::string& directory, const SlurmOptions& options,
                           const std::function<void(const nlohmann::ordered_json&)>& done);

// One array element: runs its share of the directory's configurations.
void runSlurmTask(const std::string& directory, int task);

}  // namespace rtu
