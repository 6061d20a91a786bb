// rtusim: a model of the sparse voxel octree ray tracing unit of Espe (2019).

#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>

#include <CLI/CLI.hpp>

#include "app/commands.h"
#include "base/output_file.h"
#include "base/work_phase.h"
#include "config/configuration.h"

int main(int argc, char** argv) {
  CLI::App app{"rtusim: models of a ray tracing unit for sparse voxel octrees"};
  app.set_version_flag("--version", rtu::rtusimVersion());
  app.require_subcommand(1);
  rtu::addBuildCommand(app);
  rtu::addValidateCommand(app);
  rtu::addJobsCommand(app);
  rtu::addGoldenCommand(app);
  rtu::addReplayCommand(app);
  rtu::addRenderCommand(app);
  rtu::addAnimateCommand(app);
  rtu::addAccuracyCommand(app);
  rtu::addPrecisionCommand(app);
  rtu::addConfigCommand(app);
  rtu::addStatsCommand(app);
  rtu::addFpsCommand(app);
  rtu::addFidelityCommand(app);
  rtu::addSweepCommand(app);
  rtu::addCompareCommand(app);
  rtu::addPlotCommands(app);
  rtu::addDiffCommand(app);
  rtu::addWaveCommand(app);
  // RTUSIM_PARSE_ONLY=1: check a command line (options, values, required options) and run
  // nothing; tests/doc_examples.py checks so the examples too long to run in the suite. The
  // application's own callback runs once every requirement is checked, before the command's.
  struct ParsedOnly {};
  if (const char* parseOnly = std::getenv("RTUSIM_PARSE_ONLY"); parseOnly && *parseOnly == '1')
    app.parse_complete_callback([] { throw ParsedOnly{}; });
  int status = 0;
  try {
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
      status = app.exit(error);
    }
    rtu::checkStandardOutput();  // `rtusim config --dump > /dev/full` fails
  } catch (const ParsedOnly&) {
    return 0;
  } catch (const std::bad_alloc&) {
    // The allocation names nothing: say which command ran out of memory, doing what.
    const auto commands = app.get_subcommands();
    const std::string& phase = rtu::currentWorkPhase();
    std::cerr << "rtusim: error: " << (commands.empty() ? "rtusim" : commands[0]->get_name())
              << " ran out of memory" << (phase.empty() ? "" : " while " + phase)
              << " (std::bad_alloc)\n";
    return 1;
  } catch (const std::exception& error) {
    std::cerr << "rtusim: error: " << error.what() << "\n";
    return 1;
  }
  return status;
}
