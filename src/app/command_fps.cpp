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
#include "explore/exploration_run.h"
#include "explore/sweep_workers.h"

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

void printTable(const std::vector<nlohmann::ordered_json>& rows, std::ostream& out) {
  out << std::left << std::setw(11) << "resolution" << std::right << std::setw(6) << "cores"
      << std::setw(10) << "rays" << std::setw(14) << "total cycles" << std::setw(11) << "cycles/ray"
      << std::setw(11) << "frame ms" << std::setw(10) << "fps"
      << "  limit\n";
  for (const nlohmann::ordered_json& row : rows) {
    const auto& config = row["config"];
    out << std::left << std::setw(11) << frameOf(config) << std::right << std::setw(6)
        << config["cores"].get<int>();
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
  file << csvLine(header);
  for (const nlohmann::ordered_json& row : rows) {
    const auto& config = row["config"];
    // A recorded workload's rows have no frame size: its rays are the buffer's (in the .jsonl).
    const bool recorded = !recordedBuffer(config).empty();
    std::vector<std::string> fields = {recorded ? "" : config["width"].dump(),
                                       recorded ? "" : config["height"].dump(),
                                       config["cores"].dump()};
    for (const std::string& value : statisticsValues(row)) fields.push_back(value);
    fields.push_back(row["error"].get<std::string>());
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

}  // namespace

void addFpsCommand(CLI::App& app) {
  struct Options {
    std::vector<std::string> resolutions = {"320x180", "640x360", "1280x720", "1920x1080",
                                            "3840x2160"};
    std::vector<int> cores = {1, 2, 4, 8, 16};
    std::string csv;
    int workers = defaultWorkerCount();
    bool simulate = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "fps", "frame rate per resolution and core count on the cycle-accurate model: a table in "
             "the form of thesis Tables 8.4 and 8.5");
  auto request = addConfigOptions(*command,
                                  kUseModel | kUseModelChoice | kUseArithmetic | kUseScene |
                                      kUseCamera | kUseSampling | kUseAccel | kUseBuffers,
                                  {"--cores", "--width", "--height", "--accel", "--jobs"});
  CLI::Option* resolutionsOption =
      command
          ->add_option("--resolutions", options->resolutions,
                       "WIDTHxHEIGHT list (not with a recorded workload: --set jobs=FILE or "
                       "--rays FILE)")
          ->delimiter(',')
          ->capture_default_str();
  command->add_option("--cores", options->cores, "core counts")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--csv", options->csv,
                      "write the rows: width,height,cores,rays,total_cycles,cycles_per_ray,"
                      "frame_ms,fps,limit, then more statistics; the rows in full as JSON lines "
                      "beside it (.jsonl)");
  command->add_flag("--simulate", options->simulate,
                    "run the SystemC model even where the recurrence gives the same answer "
                    "(ideal memory, no reorder buffer, steady host links)");
  addWorkersOption(*command, options->workers, "rows run in parallel (default: all cores)", 1024);
  command->callback([options, request, resolutionsOption] {
    const Configuration base = request->resolve();
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
    std::vector<size_t> all(configurations.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = i;
    std::vector<nlohmann::ordered_json> rows(configurations.size());
    const size_t failures = runRows(
        configurations, all, options->workers, "fps",
        [&rows](size_t i, const nlohmann::ordered_json& row) { rows[i] = row; },
        options->simulate ? RowModel::Simulation : RowModel::RecurrenceWhereExact);
    const RunConfig& settings = base.values();
    std::cout << "scene "
              << (settings.scene.svoFile.empty() && settings.scene.meshFile.empty() &&
                          settings.scene.binvoxFile.empty()
                      ? settings.scene.procedural + " (depth " +
                            std::to_string(settings.scene.depth) + ")"
                      : settings.scene.svoFile + settings.scene.meshFile +
                            settings.scene.binvoxFile)
              << ", " << toString(settings.rtu.scheduler) << ", "
              << (settings.rtu.memory.ideal ? "ideal" : "cached") << " memory, "
              << settings.rtu.clockMhz << " MHz, " << answeredBy(rows) << "\n";
    printTable(rows, std::cout);
    printMatrix(rows, options->cores, std::cout);
    if (!options->csv.empty()) {
      writeCsv(rows, options->csv);
      writeJsonLines(rows, jsonLines);
      std::cout << "wrote " << options->csv << " and " << jsonLines << "\n";
    }
    if (failures > 0)
      throw std::runtime_error(std::to_string(failures) +
                               " rows failed, the first: " + firstError(rows));
  });
}

}  // namespace rtu
