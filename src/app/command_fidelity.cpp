// rtusim fidelity: one frame answered by every mode rtusim has, each against the cycle-accurate
// SystemC model (src/run/fidelity_study.h): speed, total cycles and their error, per-ray cycle
// error, hit-rate error, and whether the per-ray results equal the golden model's.

#include <cstdio>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/output_paths.h"
#include "app/schema_flags.h"
#include "base/output_file.h"
#include "explore/exploration_run.h"
#include "explore/frame_scene.h"
#include "explore/raypipe_fidelity.h"
#include "explore/raypipe_frame.h"
#include "explore/raypipe_row.h"
#include "run/fidelity_study.h"
#include "run/lt_simulation.h"

namespace rtu {
namespace {

std::string text(const std::optional<double>& value, const char* format, double scale = 1) {
  if (!value) return "-";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, format, *value * scale);
  return buffer;
}

std::string yesNo(const std::optional<bool>& value) {
  if (!value) return "-";
  return *value ? "yes" : "no";
}

void printTable(const std::vector<ModeFidelity>& modes, std::ostream& out) {
  char line[320];
  const char* heading = "%-14s %8s %11s %8s %12s %8s %25s %9s %9s %7s %7s %7s %7s %8s\n";
  std::snprintf(line, sizeof line, heading, "mode", "host s", "rays/s", "speed-up", "total cycles",
                "error", "95 % interval", "ray err", "ray p99", "L1 hit", "L1 err", "L2 hit",
                "L2 err", "results");
  out << line;
  std::snprintf(line, sizeof line, heading, "", "", "", "", "", "%", "", "mean %", "%", "%", "pts",
                "%", "pts", "= golden");
  out << line;
  for (const ModeFidelity& m : modes) {
    const std::string interval = m.totalCyclesInterval
                                     ? text(m.totalCyclesInterval->low, "[%.0f, ") +
                                           text(m.totalCyclesInterval->high, "%.0f]")
                                     : "-";
    std::snprintf(
        line, sizeof line, "%-14s %8.3f %11.4g %7.1fx %12s %8s %25s %9s %9s %7s %7s %7s %7s %8s\n",
        m.mode.c_str(), m.hostSeconds, m.raysPerHostSecond, m.speedUp,
        text(m.totalCycles, "%.0f").c_str(), text(m.totalCyclesError, "%+.3f", 100).c_str(),
        interval.c_str(), text(m.perRayErrorMean, "%.3f", 100).c_str(),
        text(m.perRayErrorP99, "%.2f", 100).c_str(), text(m.l1HitRate, "%.2f", 100).c_str(),
        text(m.l1Error, "%+.3f").c_str(), text(m.l2HitRate, "%.2f", 100).c_str(),
        text(m.l2Error, "%+.3f").c_str(), yesNo(m.resultsEqualGolden).c_str());
    out << line;
  }
}

void writeCsv(const std::vector<ModeFidelity>& modes, const std::string& path) {
  OutputFile output(path);
  std::ostream& file = output.stream();
  file << csvLine({"mode", "host_seconds", "rays_per_host_second", "speed_up", "total_cycles",
                   "total_cycles_error", "total_cycles_ci_low", "total_cycles_ci_high",
                   "per_ray_error_mean", "per_ray_error_p99", "l1_hit_rate", "l1_hit_rate_error",
                   "l2_hit_rate", "l2_hit_rate_error", "results_equal_golden"});
  const auto number = [](const std::optional<double>& value) {
    return value ? text(value, "%.10g") : std::string();
  };
  for (const ModeFidelity& m : modes) {
    const std::string low = m.totalCyclesInterval ? number(m.totalCyclesInterval->low) : "";
    const std::string high = m.totalCyclesInterval ? number(m.totalCyclesInterval->high) : "";
    file << csvLine({m.mode, number(m.hostSeconds), number(m.raysPerHostSecond), number(m.speedUp),
                     number(m.totalCycles), number(m.totalCyclesError), low, high,
                     number(m.perRayErrorMean), number(m.perRayErrorP99), number(m.l1HitRate),
                     number(m.l1Error), number(m.l2HitRate), number(m.l2Error),
                     m.resultsEqualGolden ? yesNo(m.resultsEqualGolden) : ""});
  }
  output.commit();
}

// The sampled fractions the frame can take. A fraction given on the command line that is too
// small for the frame is refused, up front; a default one is skipped with a note, so that
// `fidelity` on a small frame measures the other modes instead of refusing them all.
std::vector<double> plannedFractions(const std::vector<double>& asked, bool given, uint64_t rays,
                                     const RunConfig& settings) {
  std::vector<double> planned;
  for (double fraction : asked) {
    SampleSpec spec = settings.sample;
    spec.fraction = fraction;
    try {
      planSample(rays, settings.rtu.cores, spec);
      planned.push_back(fraction);
    } catch (const std::invalid_argument& error) {
      if (given) throw;
      std::cout << "note: the sampled mode at " << fraction
                << " is skipped (a default fraction; --fractions asks for it): " << error.what()
                << "\n";
    }
  }
  return planned;
}

// fidelity --architecture raypipe (explore/raypipe_fidelity.h): the per-cycle reference, the
// timed model and the golden traversal on the frame; an error after the table when they differ.
void raypipeFidelity(const Configuration& configuration, const std::string& csv) {
  const RunConfig& settings = configuration.values();
  checkRaypipeFrameRuns(settings);
  std::vector<NamedPath> inputs = inputPaths(settings);
  inputs.push_back({"--accel-file", settings.accel.file});
  checkOutputPaths({{"--csv", csv}}, inputs);
  const FrameScene scene = loadFrameScene(settings);
  const PrgFrameSize size = raypipeFrameSize(settings);
  std::cout << "scene " << scene.name << ", " << size.width << "x" << size.height
            << ", ray pipe (seed 001); errors against its per-cycle reference\n";
  const std::vector<ModeFidelity> modes = measureRaypipeFidelity(settings, scene);
  printTable(modes, std::cout);
  if (!csv.empty()) {
    writeCsv(modes, csv);
    std::cout << "wrote " << csv << "\n";
  }
  if (!raypipeModesAgree(modes))
    throw std::logic_error("the ray pipe's timed model, its per-cycle reference and its golden "
                           "traversal differ on this frame: a model defect (docs/raypipe.md)");
}

}  // namespace

void addFidelityCommand(CLI::App& app) {
  struct Options {
    std::vector<double> fractions = {0.02, 0.05, 0.1};
    std::vector<uint64_t> quanta = {100, 1000, 10000};
    std::string csv;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "fidelity",
      "one frame answered by every mode (SystemC, recurrence, loosely-timed, sampled, golden), "
      "each measured "
      "against the cycle-accurate SystemC model: speed and error (seed 001's ray pipe: its "
      "timed model and golden traversal against its per-cycle reference)");
  auto request = addConfigOptions(*command,
                                  kUseModel | kUseArithmetic | kUseScene | kUseCamera |
                                      kUseSampling | kUseAccel | kUseBuffers,
                                  {"--sample", "--accel"});
  // The sampled modes take the sampling settings at the fractions below, not at sample.fraction.
  request->commandSets = [](RunConfig& settings) { settings.sample.fraction = 0.1; };
  CLI::Option* fractionsOption =
      command->add_option("--fractions", options->fractions, "sampled fractions to measure")
          ->delimiter(',')
          ->capture_default_str();
  CLI::Option* quantaOption =
      command
          ->add_option("--quanta", options->quanta,
                       "global quanta (cycles) of the loosely-timed model to measure")
          ->delimiter(',')
          ->check(CLI::Range(uint64_t{1}, uint64_t{1000000000}))
          ->capture_default_str();
  command->add_option("--csv", options->csv, "write one row per mode");
  command->callback([options, request, fractionsOption, quantaOption] {
    const Configuration configuration = request->resolve();
    const RunConfig& settings = configuration.values();
    if (settings.architecture == Architecture::Raypipe) {
      if (quantaOption->count() > 0 || fractionsOption->count() > 0)
        throw std::invalid_argument("--quanta, --fractions: the ray pipe has no loosely-timed or "
                                    "sampled mode; its timed model is exact (docs/raypipe.md)");
      return raypipeFidelity(configuration, options->csv);
    }
    settings.camera.validate();
    validate(settings.rtu);
    checkOutputPaths({{"--csv", options->csv}}, inputPaths(settings));
    const FrameScene scene = loadFrameScene(settings);
    const std::vector<HostRecord> jobs = frameRecords(scene, settings);
    // As the sampled fractions: asked-for quanta are refused, the default ones skipped with a note.
    std::vector<uint64_t> quanta = options->quanta;
    if (const auto why = whyNotLooselyTimed(settings.rtu); why && !quanta.empty()) {
      if (quantaOption->count() > 0)
        throw std::invalid_argument("--quanta: the loosely-timed model does not apply: " + *why);
      std::cout << "note: the loosely-timed modes are skipped (default quanta; --quanta asks for "
                   "them): "
                << *why << "\n";
      quanta.clear();
    }
    const std::vector<double> fractions =
        plannedFractions(options->fractions, fractionsOption->count() > 0, jobs.size(), settings);
    std::cout << "scene " << scene.name << ", " << settings.camera.width << "x"
              << settings.camera.height << ", " << settings.rtu.cores << " cores, "
              << (settings.rtu.memory.ideal ? "ideal" : "cached") << " memory; errors against "
              << "the SystemC model\n";
    const std::vector<ModeFidelity> modes =
        measureFidelity(scene.memory(), jobs, settings.rtu, quanta, fractions, settings.sample);
    printTable(modes, std::cout);
    if (!options->csv.empty()) {
      writeCsv(modes, options->csv);
      std::cout << "wrote " << options->csv << "\n";
    }
  });
}

}  // namespace rtu
