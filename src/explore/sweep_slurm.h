#pragma once
// A sweep as a Slurm job array. The submitting rtusim writes a sweep directory (on a file system
// the cluster's nodes share): the configurations still to run, the scenes built once, and a batch
// script whose array elements each run `rtusim sweep --slurm-task ID --sweep-dir DIR` on every
// tasks-th configuration, appending rows to their own file. It submits with `sbatch --wait`,
// shows progress from the rows written, and hands every row to the caller (which writes the
// sweep's CSV and JSON lines as a local sweep does). See docs/slurm.md.

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/configuration.h"

namespace rtu {

struct SlurmOptions {
  std::string partition;  // empty: the cluster's default
  int tasks = 0;          // array elements; 0: one per configuration, at most 256
  bool dryRun = false;    // write the directory and the batch script, do not submit
};

// Configurations that are not valid (validRows) go to `done` as invalid rows and are not
// submitted. Returns the path of the batch script.
std::string runRowsOnSlurm(const std::vector<Configuration>& configurations,
                           const std::vector<size_t>& rows, const std::string& directory,
                           const SlurmOptions& options,
                           const std::function<void(const nlohmann::ordered_json&)>& done);

// One array element: runs its share of the directory's configurations.
void runSlurmTask(const std::string& directory, int task);

}  // namespace rtu
