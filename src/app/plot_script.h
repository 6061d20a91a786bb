#pragma once
// The plotting script (scripts/rtusim_plot.py, matplotlib), embedded in the binary and run with
// python3, so plots work wherever the binary is.

#include <string>
#include <vector>

namespace rtu {

// Runs `python3 rtusim_plot.py SUBCOMMAND ARGS...`; throws std::runtime_error when it fails.
void runPlotScript(const std::string& subcommand, const std::vector<std::string>& arguments);

}  // namespace rtu
