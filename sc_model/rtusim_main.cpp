// rtusim: a model of the sparse voxel octree ray tracing unit of Espe (2019).

#include <malloc.h>

#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "configuration.h"

namespace {

// A run's big vectors (records, results, arrival cycles: tens of MB each at 720p) would each be
// mapped fresh and handed back to the kernel when freed, which then zeroes every page again for
// the next one (page faults are about a fifth of a replay's time). Kept in the heap, freed memory
// serves later vectors: a 1280x720 replay faults 47 k pages instead of 54 k.
void keepFreedMemory() {
  constexpr int kLargest = 1 << 30;  // mallopt's threshold argument is an int
  mallopt(M_MMAP_THRESHOLD, kLargest);
  mallopt(M_TRIM_THRESHOLD, kLargest);
}

}  // namespace

int main(int argc, char** argv) {
  keepFreedMemory();
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
  rtu::addFpsCommand(app);
  rtu::addFidelityCommand(app);
  rtu::addSweepCommand(app);
  rtu::addPlotCommands(app);
  rtu::addWaveCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const std::exception& error) {
    std::cerr << "rtusim: error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
