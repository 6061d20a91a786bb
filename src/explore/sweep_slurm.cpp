#include "explore/sweep_slurm.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <stdexcept>
#include <thread>

#include "base/input_file.h"
#include "base/output_file.h"
#include "explore/exploration_run.h"
#include "explore/sweep_workers.h"

extern char** environ;

namespace rtu {
namespace {

using Json = nlohmann::ordered_json;
namespace fs = std::filesystem;

std::string rowsFile(const std::string& directory, int task) {
  return directory + "/rows_" + std::to_string(task) + ".jsonl";
}

// Calls row(json) for each row in a task's file, one at a time; a line cut short (the task was
// killed) is left out.
void forEachRow(const std::string& path, const std::function<void(const Json&)>& row) {
  std::ifstream in = openInputFileIfAny(path, "sweep rows");
  std::string line;
  while (std::getline(in, line)) {
    Json parsed;
    try {
      parsed = Json::parse(line);
    } catch (const nlohmann::json::exception&) {
      continue;
    }
    row(parsed);
  }
}

// What the directory holds of the sweep: its points and the indices to run.
struct SweepPlan {
  SweepPoints points;
  IndexRanges rows;
  int tasks;
};

SweepPlan readPlan(const std::string& directory) {
  const std::string path = directory + "/plan.json";
  // The rows' ranges grow with the rows done before, not with the grid.
  const Json plan = Json::parse(readInputFile(path, "sweep plan", uint64_t{1} << 30));
  try {
    return {SweepPoints::fromJson(plan.at("points")),
            IndexRanges::parse(plan.at("rows").get<std::string>()), plan.at("tasks").get<int>()};
  } catch (const std::exception& error) {
    throw std::runtime_error("sweep plan '" + path + "': " + error.what());
  }
}

void writeBatchScript(const std::string& path, const std::string& directory, int tasks,
                      const SlurmOptions& options) {
  const std::string rtusim = fs::read_symlink("/proc/self/exe").string();
  OutputFile file(path);
  std::ostream& script = file.stream();
  script << "#!/bin/bash\n"
         << "# Written by rtusim sweep --slurm: array element i runs rows i, i+" << tasks
         << ", ... of plan.json's rows.\n"
         << "#SBATCH --job-name=rtusim-sweep\n"
         << "#SBATCH --array=0-" << tasks - 1 << "\n"
         << "#SBATCH --ntasks=1\n"
         << "#SBATCH --cpus-per-task=1\n"
         << "#SBATCH --output=" << directory << "/task_%a.log\n";
  if (!options.partition.empty()) script << "#SBATCH --partition=" << options.partition << "\n";
  script << "exec '" << rtusim << "' sweep --slurm-task \"$SLURM_ARRAY_TASK_ID\" --sweep-dir '"
         << directory << "'\n";
  file.commit();
}

size_t countRows(const std::string& directory, int tasks) {
  size_t rows = 0;
  for (int task = 0; task < tasks; ++task) {
    std::ifstream in = openInputFileIfAny(rowsFile(directory, task), "sweep rows");
    rows += static_cast<size_t>(std::count(std::istreambuf_iterator<char>(in), {}, '\n'));
  }
  return rows;
}

// sbatch --wait, with progress from the rows the tasks have written meanwhile.
void submitAndWait(const std::string& script, const std::string& directory, int tasks,
                   size_t total) {
  std::vector<std::string> words = {"sbatch", "--wait", "--parsable", script};
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (::posix_spawnp(&pid, "sbatch", nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot run sbatch: is Slurm installed and SLURM_CONF set?");
  Progress progress("slurm", total);
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    progress.update(countRows(directory, tasks), 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  progress.finish();
  // sbatch --wait exits non-zero when an array element failed; the rows say which.
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    std::cerr << "rtusim: warning: sbatch --wait ended with status " << WEXITSTATUS(status)
              << "; rows missing below run again next time\n";
}

// Removes an earlier plan's directory; refuses one the sweep did not make (a plan.json marks it),
// whose files are not the sweep's to delete.
void clearSweepDirectory(const std::string& directory) {
  std::error_code error;
  if (!fs::exists(directory, error)) return;
  if (!fs::is_directory(directory, error) ||
      (!fs::is_empty(directory, error) && !fs::exists(directory + "/plan.json", error)))
    throw std::invalid_argument("sweep directory '" + directory +
                                "' exists and is not one a sweep made (no plan.json): give "
                                "another --sweep-dir, or remove it");
  fs::remove_all(directory);
}

}  // namespace

std::string runRowsOnSlurm(const SweepPoints& points, const IndexRanges& allRows,
                           const std::string& directoryName, const SlurmOptions& options,
                           const std::function<void(const Json&)>& done) {
  IndexRanges rows;
  SceneCache scenes;
  allRows.forEach([&](size_t row) {
    const Configuration configuration = points.at(row);
    try {
      validateRow(configuration);
      rows.add(row);
      scenes.need(configuration);
    } catch (const std::invalid_argument& error) {
      done(failedRow(configuration, error.what(), "invalid"));
    }
  });
  const std::string directory = fs::absolute(directoryName).string();
  clearSweepDirectory(directory);  // a fresh plan: rows already done are in the sweep's own files
  fs::create_directories(directory);
  const size_t count = rows.count();
  const int tasks = static_cast<int>(
      std::max<size_t>(1, std::min<size_t>(count, options.tasks > 0 ? options.tasks : 256)));
  writeTextFile(directory + "/plan.json",
                Json{{"tasks", tasks}, {"rows", rows.text()}, {"points", points.toJson()}}.dump() +
                    "\n");
  scenes.build();
  scenes.save(directory);
  const std::string script = directory + "/sweep.sbatch";
  writeBatchScript(script, directory, tasks, options);
  if (options.dryRun || count == 0) return script;
  submitAndWait(script, directory, tasks, count);
  for (int task = 0; task < tasks; ++task) forEachRow(rowsFile(directory, task), done);
  return script;
}

void runSlurmTask(const std::string& directory, int task) {
  const SweepPlan plan = readPlan(directory);
  if (task < 0 || task >= plan.tasks)
    throw std::invalid_argument("--slurm-task " + std::to_string(task) + " is not in 0.." +
                                std::to_string(plan.tasks - 1));
  SceneCache scenes;
  scenes.load(directory);
  // Rows this task wrote before it was requeued or killed are kept.
  const std::string path = rowsFile(directory, task);
  std::set<std::string> done;
  forEachRow(path, [&done](const Json& row) { done.insert(row["config"].dump()); });
  std::ofstream out(path, std::ios::app);
  size_t k = 0;
  plan.rows.forEach([&](size_t row) {
    if (k++ % static_cast<size_t>(plan.tasks) != static_cast<size_t>(task)) return;
    const Configuration configuration = plan.points.at(row);
    if (done.count(configuration.toJson().dump())) return;
    out << runRowSafely(configuration, scenes).dump() << "\n" << std::flush;
  });
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace rtu
