#pragma once
// The plotting scripts (scripts/rtusim_*.py, matplotlib), embedded in the binary and run with
// python3, so plots, reports and diffs work wherever the binary is.

#include <map>
#include <string>
#include <vector>

namespace rtu {

// A subcommand's inputs and options, passed on to the script as given: each option once per value.
struct PlotArguments {
  std::vector<std::string> inputs;
  std::map<std::string, std::string> values;                // "--x" -> its value, once
  std::map<std::string, std::vector<std::string>> options;  // "--where" -> values, repeatable
  std::map<std::string, bool> flags;                        // "--changed" -> set

  std::vector<std::string> arguments() const;
};

// Runs `python3 rtusim_plot.py SUBCOMMAND ARGS...`; throws std::runtime_error when it fails.
void runPlotScript(const std::string& subcommand, const std::vector<std::string>& arguments);

}  // namespace rtu
