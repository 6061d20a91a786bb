#pragma once
// The rtusim subcommands; each registers itself on the application.

#include <CLI/CLI.hpp>

namespace rtu {

void addBuildCommand(CLI::App& app);
void addValidateCommand(CLI::App& app);
void addJobsCommand(CLI::App& app);
void addGoldenCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addReplayCommand(CLI::App& app);
void addAccuracyCommand(CLI::App& app);
void addPrecisionCommand(CLI::App& app);
void addConfigCommand(CLI::App& app);
void addStatsCommand(CLI::App& app);
void addFidelityCommand(CLI::App& app);
void addFpsCommand(CLI::App& app);
void addSweepCommand(CLI::App& app);
void addPlotCommands(CLI::App& app);  // plot, report and best
void addDiffCommand(CLI::App& app);
void addWaveCommand(CLI::App& app);
void addAnimateCommand(CLI::App& app);
void addCompareCommand(CLI::App& app);

}  // namespace rtu
