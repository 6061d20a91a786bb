#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/input_file_check.h"
#include "app/output_paths.h"
#include "app/plot_script.h"
#include "app/schema_flags.h"
#include "app/sweep_earlier_rows.h"
#include "app/workers_option.h"
#include "base/file_lock.h"
#include "base/input_file.h"
#include "base/output_file.h"
#include "config/sweep_points.h"
#include "config/sweep_spec.h"
#include "explore/architecture_resources.h"
#include "explore/exploration_run.h"
#include "explore/sweep_slurm.h"
#include "explore/sweep_workers.h"

namespace rtu {
namespace {

using Json = nlohmann::ordered_json;

// A configuration key that also names a statistics column (`rays`: the ray-buffer file and the
// count of rays) is the column config.KEY, so that every column name is unique.
std::string configColumn(const std::string& key) {
  const std::vector<std::string>& statistics = statisticsColumns();
  return std::find(statistics.begin(), statistics.end(), key) == statistics.end() ? key
                                                                                  : "config." + key;
}

std::vector<std::string> csvHeader() {
  std::vector<std::string> header;
  for (const Setting& setting : configSchema()) header.push_back(configColumn(setting.key));
  header.push_back("status");
  header.push_back("error");
  for (const std::string& column : statisticsColumns()) header.push_back(column);
  for (const std::string& column : resourceColumns()) header.push_back(column);
  return header;
}

std::vector<std::string> csvFields(const Json& row) {
  std::vector<std::string> fields;
  for (const Setting& setting : configSchema()) {
    const Json& value = row["config"][setting.key];
    fields.push_back(value.is_string() ? value.get<std::string>() : value.dump());
  }
  fields.push_back(row["status"].get<std::string>());
  fields.push_back(row["error"].get<std::string>());
  for (const std::string& value : statisticsValues(row)) fields.push_back(value);
  for (const std::string& value : resourceValues(row)) fields.push_back(value);
  return fields;
}

// Rewrites the CSV and JSON-lines files with the earlier rows kept (each whole or not at all, as
// any output), then appends rows as they finish, each flushed at once so that an interrupted sweep
// resumes from the rows written.
class RowWriter {
 public:
  RowWriter(const std::string& csvPath, const EarlierRows& earlier) : csvPath_(csvPath) {
    OutputFile csv(csvPath), jsonLines(jsonLinesPath(csvPath));
    csv.stream() << csvLine(csvHeader());
    earlier.forEachKept([&](const Json& row) {
      csv.stream() << csvLine(csvFields(row));
      jsonLines.stream() << row.dump() << "\n";
    });
    jsonLines.commit();
    csv.commit();
    csv_.open(csvPath, std::ios::app);
    jsonLines_.open(jsonLinesPath(csvPath), std::ios::app);
    check();
  }
  void write(const Json& row) {
    csv_ << csvLine(csvFields(row)) << std::flush;
    jsonLines_ << row.dump() << "\n" << std::flush;
    check();
  }

 private:
  void check() const {
    if (!csv_ || !jsonLines_)
      throw std::runtime_error("cannot write '" + csvPath_ + "' and '" + jsonLinesPath(csvPath_) +
                               "': " + std::strerror(errno));
  }

  std::string csvPath_;
  std::ofstream csv_, jsonLines_;
};

// This run's rows as they finish: written (a lost row only reported), counted, the first error
// kept.
class SweepTally {
 public:
  explicit SweepTally(RowWriter& writer) : writer_(writer) {}
  void add(const Json& row) {
    const std::string status = row["status"].get<std::string>();
    if (status != "ok" && firstError_.empty()) firstError_ = row["error"].get<std::string>();
    if (status == "lost") {
      std::cerr << "rtusim: sweep: row lost, it runs again next time: "
                << row["error"].get<std::string>() << "\n";
      return;
    }
    writer_.write(row);
    ++written_;
    ok_ += status == "ok";
    invalid_ += status == "invalid";
  }
  // The summary of `pending` rows.
  void report(size_t pending, const std::string& files) const {
    std::cout << "sweep: " << ok_ << " rows done, " << written_ - ok_ << " failed"
              << (invalid_ > 0 ? " (" + std::to_string(invalid_) + " invalid)" : "") << ", "
              << pending - written_ << " lost; wrote " << files << "\n";
  }
  // One rule for the exit status: throws std::runtime_error with the first error when any of the
  // `pending` rows failed, was invalid or was lost.
  void check(size_t pending) const {
    const std::string first = firstError_.empty() ? "no row came back" : firstError_;
    if (pending > 0 && ok_ == 0)
      throw std::runtime_error("every row of the sweep failed, the first: " + first);
    if (ok_ < pending)
      throw std::runtime_error(std::to_string(pending - ok_) + " rows failed, the first: " + first);
  }

 private:
  RowWriter& writer_;
  size_t written_ = 0, ok_ = 0, invalid_ = 0;
  std::string firstError_;
};

// Before any row runs or any file is touched, every point once as it is computed (none is held):
// the architecture the command runs, and the keys without effect (SettingsEffectCheck).
void checkPoints(const SweepPoints& points, const ConfigRequest& request,
                 const std::string& sweepFile) {
  SettingsEffectCheck effect(request.uses, request.command);
  for (size_t i = 0; i < points.size(); ++i) {
    const Configuration configuration = points.at(i);
    checkArchitectureRuns(configuration, request.command, request.uses);
    effect.add(configuration);
  }
  try {
    effect.finish();
  } catch (const std::invalid_argument& error) {
    // The swept key may be the file's: the error names it (a fuzzed file's key did not).
    if (sweepFile.empty()) throw;
    throw std::invalid_argument("sweep file '" + sweepFile + "': " + error.what());
  }
}

// The points without a finished earlier row, as index ranges (held by the rows done, not the
// grid).
IndexRanges pointsToRun(const SweepPoints& points, EarlierRows& earlier) {
  if (earlier.empty()) return IndexRanges::span(0, points.size());
  IndexRanges pending;
  for (size_t i = 0; i < points.size(); ++i)
    if (!earlier.sweep(points.at(i).toJson().dump())) pending.add(i);
  return pending;
}

// A dry run's plan, whatever the grid's size: the count and the first and last rows to run.
void printPlan(const SweepPoints& points, const IndexRanges& pending) {
  if (pending.empty()) {
    std::cout << "sweep: rows to run: 0\n";
    return;
  }
  std::cout << "sweep: rows to run: " << pending.count() << ", the first (" << pending.first()
            << ") " << points.describe(pending.first()) << ", the last (" << pending.last() << ") "
            << points.describe(pending.last()) << "\n";
}

}  // namespace

void addSweepCommand(CLI::App& app) {
  struct Options {
    std::vector<std::string> grid;
    std::string sweepFile;
    std::string out = "sweep.csv";
    std::string plotDir;
    int workers = defaultWorkerCount();
    bool slurm = false;
    SlurmOptions slurmOptions;
    int slurmTask = -1;
    std::string sweepDir;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "sweep", "run a grid and/or list of configurations on the cycle-accurate model in parallel "
               "workers: one row per configuration in CSV and JSON lines, resumable");
  // The accel settings of a triangle core's build (--builder, --drop-bad-triangles), as render's.
  auto request =
      addConfigOptions(*command,
                       kUseModel | kUseModelChoice | kUseArithmetic | kUseScene | kUseCamera |
                           kUseSampling | kUseAccel | kUseBuffers | kUseWorkload,
                       {"--accel", "--jobs"});
  command->add_option("--grid", options->grid,
                      "key=v1,v2,...: the sweep is the product of all grids (repeatable)");
  command
      ->add_option("--sweep-file", options->sweepFile,
                   "TOML sweep: [grid] key = [values], [[configs]] explicit configurations")
      ->check(regularInputFile());
  command
      ->add_option("--out", options->out,
                   "rows as CSV; JSON lines beside it (.jsonl). Rows already there are kept "
                   "and not run again")
      ->capture_default_str();
  addWorkersOption(*command, options->workers,
                   "configurations run in parallel (default: all cores)", 1024);
  command->add_option("--plot", options->plotDir,
                      "write plots of the rows (PNG, SVG) into this folder");
  command->add_flag("--slurm", options->slurm,
                    "run the rows as a Slurm job array (sbatch --wait) instead of local workers");
  command->add_option("--slurm-partition", options->slurmOptions.partition, "Slurm partition");
  command
      ->add_option("--slurm-tasks", options->slurmOptions.tasks,
                   "array elements, each running every n-th row (default: a row each, at most 256)")
      ->check(CLI::Range(1, 100000));
  command->add_flag("--dry-run", options->slurmOptions.dryRun,
                    "check the grid and say which rows would run, run none (with --slurm: write "
                    "the sweep directory and batch script, do not submit)");
  command->add_option("--sweep-dir", options->sweepDir,
                      "with --slurm: the shared directory of the job array (default: OUT.slurm)");
  command->add_option("--slurm-task", options->slurmTask,
                      "internal: run one array element of the sweep in --sweep-dir");
  command->callback([options, request] {
    if (options->slurmTask >= 0) {
      if (options->sweepDir.empty()) throw std::invalid_argument("--slurm-task needs --sweep-dir");
      return runSlurmTask(options->sweepDir, options->slurmTask);
    }
    SweepSpec spec;
    if (!options->sweepFile.empty()) spec.loadFile(options->sweepFile);
    for (const std::string& grid : options->grid) spec.addGrid(grid);
    const SweepPoints points(spec, request->resolveUnchecked());
    checkPoints(points, *request, options->sweepFile);

    // One sweep at a time writes these files: a second one is refused, naming the first.
    const FileLock lock(options->out + ".lock", "sweep output '" + options->out + "'");
    EarlierRows earlier(jsonLinesPath(options->out));
    const IndexRanges pending = pointsToRun(points, earlier);
    const size_t alreadyDone = points.size() - pending.count();
    const size_t others = earlier.keptCount() - alreadyDone;
    std::cout << "sweep: " << points.size() << " configurations, " << alreadyDone
              << " already done, " << pending.count() << " to run with " << options->workers
              << " workers"
              << (others > 0 ? "; " + std::to_string(others) + " rows of other configurations kept"
                             : "")
              << "\n"
              << std::flush;
    if (options->slurmOptions.dryRun && !options->slurm) return printPlan(points, pending);
    RowWriter writer(options->out, earlier);
    SweepTally tally(writer);
    const auto write = [&tally](const Json& row) { tally.add(row); };
    if (options->slurm) {
      const std::string directory =
          options->sweepDir.empty()
              ? std::filesystem::path(options->out).replace_extension(".slurm").string()
              : options->sweepDir;
      const std::string script =
          runRowsOnSlurm(points, pending, directory, options->slurmOptions, write);
      if (options->slurmOptions.dryRun) {
        printPlan(points, pending);
        std::cout << "sweep: wrote " << script << " (not submitted: sbatch " << script << ")\n";
        return;
      }
    } else {
      runRows([&points](size_t i) { return points.at(i); }, pending, options->workers, "sweep",
              [&](size_t, const Json& row) { write(row); });
    }
    tally.report(pending.count(), options->out + " and " + jsonLinesPath(options->out));
    if (!options->plotDir.empty())
      runPlotScript("plot", {"--out-dir", options->plotDir, jsonLinesPath(options->out)});
    tally.check(pending.count());
  });
}

}  // namespace rtu
