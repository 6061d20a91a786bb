#include "explore/sweep_slurm.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
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

// The rows in a task's file; a line cut short (the task was killed) is left out.
std::vector<Json> readRows(const std::string& path) {
  std::vector<Json> rows;
  std::ifstream in = openInputFileIfAny(path, "sweep rows");
  std::string line;
  while (std::getline(in, line)) {
    try {
      rows.push_back(Json::parse(line));
    } catch (const nlohmann::json::exception&) {
    }
  }
  return rows;
}

std::vector<Configuration> readConfigurations(const std::string& directory) {
  uint64_t bytes = 0;
  std::ifstream in = openInputFile(directory + "/configs.jsonl", "sweep configurations", bytes);
  std::vector<Configuration> configurations;
  std::string line;
  while (std::getline(in, line)) {
    Configuration configuration;
    configuration.loadText(line, "json", "configs.jsonl", ConfigSource::File);
    configurations.push_back(configuration);
  }
  return configurations;
}

void writeBatchScript(const std::string& path, const std::string& directory, int tasks,
                      const SlurmOptions& options) {
  const std::string rtusim = fs::read_symlink("/proc/self/exe").string();
  OutputFile file(path);
  std::ostream& script = file.stream();
  script << "#!/bin/bash\n"
         << "# Written by rtusim sweep --slurm: array element i runs configurations i, i+" << tasks
         << ", ... of configs.jsonl.\n"
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

std::string runRowsOnSlurm(const std::vector<Configuration>& configurations,
                           const std::vector<size_t>& allRows, const std::string& directoryName,
                           const SlurmOptions& options,
                           const std::function<void(const Json&)>& done) {
  const std::vector<size_t> rows =
      validRows(configurations, allRows, [&done](size_t, const Json& row) { done(row); });
  const std::string directory = fs::absolute(directoryName).string();
  clearSweepDirectory(directory);  // a fresh plan: rows already done are in the sweep's own files
  fs::create_directories(directory);
  const int tasks = static_cast<int>(
      std::max<size_t>(1, std::min<size_t>(rows.size(), options.tasks > 0 ? options.tasks : 256)));
  std::vector<Configuration> pending;
  std::string plan;
  for (size_t row : rows) {
    plan += configurations[row].toJson().dump() + "\n";
    pending.push_back(configurations[row]);
  }
  writeTextFile(directory + "/configs.jsonl", plan);
  writeTextFile(directory + "/plan.json", Json{{"tasks", tasks}}.dump() + "\n");
  SceneCache scenes;
  scenes.build(pending);
  scenes.save(directory);
  const std::string script = directory + "/sweep.sbatch";
  writeBatchScript(script, directory, tasks, options);
  if (options.dryRun || rows.empty()) return script;
  submitAndWait(script, directory, tasks, rows.size());
  for (int task = 0; task < tasks; ++task)
    for (const Json& row : readRows(rowsFile(directory, task))) done(row);
  return script;
}

void runSlurmTask(const std::string& directory, int task) {
  const int tasks = nlohmann::json::parse(readInputFile(directory + "/plan.json", "sweep plan",
                                                        kMaxSettingsFileBytes))["tasks"]
                        .get<int>();
  if (task < 0 || task >= tasks)
    throw std::invalid_argument("--slurm-task " + std::to_string(task) + " is not in 0.." +
                                std::to_string(tasks - 1));
  const std::vector<Configuration> configurations = readConfigurations(directory);
  SceneCache scenes;
  scenes.load(directory);
  // Rows this task wrote before it was requeued or killed are kept.
  const std::string path = rowsFile(directory, task);
  std::vector<std::string> done;
  for (const Json& row : readRows(path)) done.push_back(row["config"].dump());
  std::ofstream out(path, std::ios::app);
  for (size_t i = static_cast<size_t>(task); i < configurations.size();
       i += static_cast<size_t>(tasks)) {
    const std::string key = configurations[i].toJson().dump();
    if (std::find(done.begin(), done.end(), key) != done.end()) continue;
    out << runRowSafely(configurations[i], scenes).dump() << "\n" << std::flush;
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace rtu
