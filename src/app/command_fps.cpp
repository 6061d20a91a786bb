#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "app/commands.h"
#include "app/output_paths.h"
#include "app/schema_flags.h"
#include "app/workers_option.h"
#include "base/output_file.h"
#include "explore/architecture_resources.h"
#include "explore/exploration_run.h"
#include "explore/raypipe_row.h"
#include "explore/sweep_workers.h"
#include "raypipe/primary_rays.h"

namespace rtu {
namespace {

struct Resolution {
  int width, height;
};

Resolution parseResolution(const std::string& text) {
  const size_t x = text.find('x');
  try {
    if (x != std::string::npos) {
      size_t usedWidth = 0, usedHeight = 0;
      const int width = std::stoi(text.substr(0, x), &usedWidth);
      const int height = std::stoi(text.substr(x + 1), &usedHeight);
      if (usedWidth == x && usedHeight == text.size() - x - 1) return {width, height};
    }
  } catch (const std::exception&) {
  }
  throw std::invalid_argument("--resolutions: '" + text + "' is not WIDTHxHEIGHT");
}

// The workload of a recorded run: its buffer's file name.
std::string workloadName(const RunConfig& settings) {
  return std::filesystem::path(settings.jobs.empty() ? settings.rays : settings.jobs)
      .filename()
      .string();
}

// The buffer of a row's recorded workload, or "" for a camera's frame.
std::string recordedBuffer(const nlohmann::ordered_json& config) {
  for (const char* buffer : {"jobs", "rays"})
    if (config.contains(buffer) && !config[buffer].get<std::string>().empty())
      return config[buffer].get<std::string>();
  return {};
}

// A row's frame: WIDTHxHEIGHT, or the recorded workload's buffer.
std::string frameOf(const nlohmann::ordered_json& config) {
  const std::string buffer = recordedBuffer(config);
  if (!buffer.empty()) return std::filesystem::path(buffer).filename().string();
  return std::to_string(config["width"].get<int>()) + "x" +
         std::to_string(config["height"].get<int>());
}

// Whether a row's configuration is the ray pipe's (docs/raypipe.md), which has no cores.
bool raypipeRow(const nlohmann::ordered_json& config) {
  return config["architecture"] == "raypipe";
}

// A row's core count, or "-" for the ray pipe.
std::string coresOf(const nlohmann::ordered_json& config) {
  return raypipeRow(config) ? "-" : config["cores"].dump();
}

void printTable(const std::vector<nlohmann::ordered_json>& rows, std::ostream& out) {
  out << std::left << std::setw(11) << "resolution" << std::right << std::setw(6) << "cores"
      << std::setw(10) << "rays" << std::setw(14) << "total cycles" << std::setw(11) << "cycles/ray"
      << std::setw(11) << "frame ms" << std::setw(10) << "fps"
      << "  limit\n";
  for (const nlohmann::ordered_json& row : rows) {
    const auto& config = row["config"];
    out << std::left << std::setw(11) << frameOf(config) << std::right << std::setw(6)
        << coresOf(config);
    if (row["status"] != "ok") {
      out << "  failed: " << row["error"].get<std::string>() << "\n";
      continue;
    }
    const auto& s = row["statistics"];
    out << std::setw(10) << s["rays"].get<uint64_t>() << std::setw(14)
        << s["total_cycles"].get<uint64_t>() << std::fixed << std::setprecision(2) << std::setw(11)
        << s["cycles_per_ray"].get<double>() << std::setw(11) << s["frame_ms"].get<double>()
        << std::setw(10) << s["fps"].get<double>() << "  " << s["limit"].get<std::string>() << " "
        << std::setprecision(1) << 100 * s["limit_utilisation"].get<double>() << " %\n";
  }
}

// Thesis Table 8.4's form: one line per resolution, frame time and rate per core count.
void printMatrix(const std::vector<nlohmann::ordered_json>& rows, const std::vector<int>& cores,
                 std::ostream& out) {
  out << "\nframe time in ms (frames/s)\n" << std::left << std::setw(11) << "resolution";
  for (int c : cores) out << std::right << std::setw(18) << (std::to_string(c) + " cores");
  out << "\n";
  for (size_t first = 0; first < rows.size(); first += cores.size()) {
    const auto& config = rows[first]["config"];
    out << std::left << std::setw(11) << frameOf(config);
    for (size_t i = first; i < first + cores.size(); ++i) {
      std::ostringstream cell;
      if (rows[i]["status"] == "ok")
        cell << std::fixed << std::setprecision(2)
             << rows[i]["statistics"]["frame_ms"].get<double>() << " (" << std::setprecision(1)
             << rows[i]["statistics"]["fps"].get<double>() << ")";
      else
        cell << "failed";
      out << std::right << std::setw(18) << cell.str();
    }
    out << "\n";
  }
}

void writeCsv(const std::vector<nlohmann::ordered_json>& rows, const std::string& path) {
  OutputFile output(path);
  std::ostream& file = output.stream();
  std::vector<std::string> header = {"width", "height", "cores"};
  for (const std::string& column : statisticsColumns()) header.push_back(column);
  header.push_back("error");
  for (const std::string& column : resourceColumns()) header.push_back(column);
  file << csvLine(header);
  for (const nlohmann::ordered_json& row : rows) {
    const auto& config = row["config"];
    // A recorded workload's rows have no frame size: its rays are the buffer's (in the .jsonl).
    const bool recorded = !recordedBuffer(config).empty();
    std::vector<std::string> fields = {recorded ? "" : config["width"].dump(),
                                       recorded ? "" : config["height"].dump(),
                                       raypipeRow(config) ? "" : coresOf(config)};
    for (const std::string& value : statisticsValues(row)) fields.push_back(value);
    fields.push_back(row["error"].get<std::string>());
    for (const std::string& value : resourceValues(row)) fields.push_back(value);
    file << csvLine(fields);
  }
  output.commit();
}

// The rows in full beside the CSV, as sweep writes them: the CSV holds three keys of the
// configuration, the report and diff read every key (and the preset) from here.
void writeJsonLines(const std::vector<nlohmann::ordered_json>& rows, const std::string& path) {
  OutputFile output(path);
  for (const nlohmann::ordered_json& row : rows) output.stream() << row.dump() << "\n";
  output.commit();
}

// The models that answered the rows, for the heading.
std::string answeredBy(const std::vector<nlohmann::ordered_json>& rows) {
  std::set<std::string> models;
  for (const nlohmann::ordered_json& row : rows)
    if (row["status"] == "ok")
      models.insert(row["statistics"]["simulation"]["model"].get<std::string>());
  std::vector<std::string> parts;
  if (models.count("recurrence"))
    parts.push_back("the exact recurrence where it applies (--simulate: SystemC)");
  if (models.count("systemc")) parts.push_back("SystemC simulation");
  if (models.count("sampled"))
    parts.push_back("sampled SystemC simulation (estimates, 95 % intervals in the CSV)");
  if (models.count("lt")) parts.push_back("the loosely-timed model (estimates, docs/fidelity.md)");
  if (models.count("golden")) parts.push_back("golden costs in the recurrence (memory as ideal)");
  if (models.count("raypipe"))
    parts.push_back("the ray pipe's timed model (exact: cycle for cycle its per-cycle reference)");
  std::string text = "answered by ";
  for (size_t i = 0; i < parts.size(); ++i) text += (i > 0 ? ", " : "") + parts[i];
  return parts.empty() ? "no row answered" : text;
}

// The error of the first failed row: with a malformed scene file every row fails alike, and the
// final message names the file.
std::string firstError(const std::vector<nlohmann::ordered_json>& rows) {
  for (const nlohmann::ordered_json& row : rows)
    if (row["status"] != "ok") return row["error"].get<std::string>();
  return {};
}

struct FpsOptions {
  std::vector<std::string> resolutions = {"320x180", "640x360", "1280x720", "1920x1080",
                                          "3840x2160"};
  std::vector<int> cores = {1, 2, 4, 8, 16};
  std::string csv;
  int workers = defaultWorkerCount();
  bool simulate = false;
};

// The scene a row's settings name, for the heading.
std::string sceneName(const RunConfig& settings) {
  const SceneSpec& scene = settings.scene;
  if (scene.svoFile.empty() && scene.meshFile.empty() && scene.binvoxFile.empty())
    return scene.procedural + " (depth " + std::to_string(scene.depth) + ")";
  return scene.svoFile + scene.meshFile + scene.binvoxFile;
}

// Runs the rows, prints `heading` with what answered them, the table (and the matrix over
// `matrixCores`, if any) and writes the CSV; throws after it all when a row failed.
void runFpsRows(const std::vector<Configuration>& configurations, const FpsOptions& options,
                RowModel model, const std::string& heading, const std::vector<int>& matrixCores) {
  std::vector<nlohmann::ordered_json> rows(configurations.size());
  const size_t failures =
      runRows([&configurations](size_t i) { return configurations[i]; },
              IndexRanges::span(0, configurations.size()), options.workers, "fps",
              [&rows](size_t i, const nlohmann::ordered_json& row) { rows[i] = row; }, model);
  std::cout << heading << ", " << answeredBy(rows) << "\n";
  printTable(rows, std::cout);
  if (!matrixCores.empty()) printMatrix(rows, matrixCores, std::cout);
  if (!options.csv.empty()) {
    const std::string jsonLines = jsonLinesPath(options.csv);
    writeCsv(rows, options.csv);
    writeJsonLines(rows, jsonLines);
    std::cout << "wrote " << options.csv << " and " << jsonLines << "\n";
  }
  if (failures > 0)
    throw std::runtime_error(std::to_string(failures) +
                             " rows failed, the first: " + firstError(rows));
}

// The resolutions of the ray pipe's rows: the seed's six levels unless --resolutions is given.
std::vector<std::string> raypipeResolutions(const FpsOptions& options, bool given) {
  if (given) return options.resolutions;
  std::vector<std::string> levels;
  for (int level = 0; level < kPrgLevels; ++level) {
    const PrgFrameSize size = prgLevelSize(level);
    levels.push_back(std::to_string(size.width) + "x" + std::to_string(size.height));
  }
  return levels;
}

// The ray pipe's level of a frame size, or -1 for another size (docs/raypipe.md, "Other sizes").
int raypipeLevel(const Resolution& resolution) {
  for (int level = 0; level < kPrgLevels; ++level) {
    const PrgFrameSize size = prgLevelSize(level);
    if (size.width == resolution.width && size.height == resolution.height) return level;
  }
  return -1;
}

// fps with architecture = raypipe: one row per resolution (the pipe has no cores), each the
// frame on the pipe's timed model (explore/raypipe_row.h). A level's size runs at that level.
void runRaypipeFps(const Configuration& base, const FpsOptions& options, bool resolutionsGiven,
                   bool coresGiven, bool simulateGiven) {
  if (coresGiven)
    throw std::invalid_argument("--cores: the ray pipe has no cores (docs/raypipe.md); its rows "
                                "are one per resolution");
  if (simulateGiven)
    throw std::invalid_argument("--simulate: the ray pipe's rows always run its timed model, "
                                "which is exact");
  const std::string jsonLines = options.csv.empty() ? "" : jsonLinesPath(options.csv);
  std::vector<NamedPath> inputs = inputPaths(base.values());
  inputs.push_back({"--accel-file", base.values().accel.file});
  checkOutputPaths({{"--csv", options.csv}, {"--csv (.jsonl)", jsonLines}}, inputs);
  std::vector<Configuration> configurations;
  for (const std::string& text : raypipeResolutions(options, resolutionsGiven)) {
    const Resolution resolution = parseResolution(text);
    Configuration configuration = base;
    configuration.set("width", std::to_string(resolution.width), ConfigSource::CommandLine);
    configuration.set("height", std::to_string(resolution.height), ConfigSource::CommandLine);
    configuration.set("raypipe.level", std::to_string(raypipeLevel(resolution)),
                      ConfigSource::CommandLine);
    validateRaypipeRow(configuration.values());
    configurations.push_back(configuration);
  }
  const RunConfig& settings = base.values();
  const RaypipeConfig& pipe = settings.raypipe;
  std::ostringstream heading;
  heading << "scene " << (settings.accel.file.empty() ? sceneName(settings) : settings.accel.file)
          << ", ray pipe (seed 001): short stack " << pipe.shortStackDepth << ", "
          << pipe.raysInFlight << " ray ids, " << pipe.clockMHz << " MHz";
  runFpsRows(configurations, options, RowModel::Simulation, heading.str(), {});
}

}  // namespace

void addFpsCommand(CLI::App& app) {
  auto options = std::make_shared<FpsOptions>();
  CLI::App* command = app.add_subcommand(
      "fps", "frame rate per resolution and core count on the cycle-accurate model: a table in "
             "the form of thesis Tables 8.4 and 8.5 (or per resolution on seed 001's ray pipe: "
             "--architecture raypipe)");
  auto request =
      addConfigOptions(*command,
                       kUseModel | kUseModelChoice | kUseArithmetic | kUseScene | kUseCamera |
                           kUseSampling | kUseAccel | kUseBuffers | kUseWorkload,
                       // fps sets the ray pipe's level per resolution.
                       {"--cores", "--width", "--height", "--level", "--accel", "--jobs"});
  CLI::Option* resolutionsOption =
      command
          ->add_option("--resolutions", options->resolutions,
                       "WIDTHxHEIGHT list (not with a recorded workload: --set jobs=FILE or "
                       "--rays FILE; the ray pipe's default: its levels, 20x15 to 640x480)")
          ->delimiter(',')
          ->capture_default_str();
  CLI::Option* coresOption = command->add_option("--cores", options->cores, "core counts")
                                 ->delimiter(',')
                                 ->capture_default_str();
  command->add_option("--csv", options->csv,
                      "write the rows: width,height,cores,rays,total_cycles,cycles_per_ray,"
                      "frame_ms,fps,limit, then more statistics; the rows in full as JSON lines "
                      "beside it (.jsonl)");
  CLI::Option* simulateOption =
      command->add_flag("--simulate", options->simulate,
                        "run the SystemC model even where the recurrence gives the same answer "
                        "(ideal memory, no reorder buffer, steady host links)");
  addWorkersOption(*command, options->workers, "rows run in parallel (default: all cores)", 1024);
  command->callback([options, request, resolutionsOption, coresOption, simulateOption] {
    const Configuration base = request->resolve();
    if (base.values().architecture == Architecture::Raypipe)
      return runRaypipeFps(base, *options, resolutionsOption->count() > 0, coresOption->count() > 0,
                           simulateOption->count() > 0);
    const bool recorded = recordedWorkload(base.values());
    if (recorded && resolutionsOption->count() > 0)
      throw std::invalid_argument("--resolutions: a recorded workload (" +
                                  workloadName(base.values()) +
                                  ") has its own rays; give one or the other");
    const std::string jsonLines = options->csv.empty() ? "" : jsonLinesPath(options->csv);
    checkOutputPaths({{"--csv", options->csv}, {"--csv (.jsonl)", jsonLines}},
                     inputPaths(base.values()));
    std::vector<Configuration> configurations;
    // A recorded workload is one "resolution": its buffer.
    const std::vector<std::string> resolutions = recorded ? std::vector<std::string>{""}
                                                          : options->resolutions;
    for (const std::string& text : resolutions) {
      for (int cores : options->cores) {
        Configuration configuration = base;
        if (!recorded) {
          const Resolution resolution = parseResolution(text);
          configuration.set("width", std::to_string(resolution.width), ConfigSource::CommandLine);
          configuration.set("height", std::to_string(resolution.height), ConfigSource::CommandLine);
        }
        configuration.set("cores", std::to_string(cores), ConfigSource::CommandLine);
        configuration.values().camera.validate();
        configurations.push_back(configuration);
      }
    }
    const RunConfig& settings = base.values();
    std::ostringstream heading;
    heading << "scene " << sceneName(settings) << ", " << toString(settings.rtu.scheduler) << ", "
            << (settings.rtu.memory.ideal
                    ? std::string("ideal memory")
                    : "cached memory (caches " + RtuStatistics::of(settings.rtu).cacheStart() + ")")
            << ", " << settings.rtu.clockMhz << " MHz";
    runFpsRows(configurations, *options,
               options->simulate ? RowModel::Simulation : RowModel::RecurrenceWhereExact,
               heading.str(), options->cores);
  });
}

}  // namespace rtu
