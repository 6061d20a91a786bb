#include <memory>

#include "app/commands.h"
#include "app/plot_script.h"

namespace rtu {

void addPlotCommands(CLI::App& app) {
  struct Options {
    std::vector<std::string> inputs;
    std::string outDir = "plots", report = "report.html";
  };
  auto options = std::make_shared<Options>();
  CLI::App* plot = app.add_subcommand(
      "plot", "plots (PNG and SVG) of sweep rows (.jsonl) or fps tables (.csv): frame rate "
              "against cores, hit rates against cache size, core time, scheduler waits, cycles "
              "per ray against DRAM latency");
  plot->add_option("inputs", options->inputs, "sweep .jsonl or fps .csv files")
      ->required()
      ->check(CLI::ExistingFile);
  plot->add_option("--out-dir", options->outDir, "folder for the plots")->capture_default_str();
  plot->callback([options] {
    std::vector<std::string> arguments = {"--out-dir", options->outDir};
    arguments.insert(arguments.end(), options->inputs.begin(), options->inputs.end());
    runPlotScript("plot", arguments);
  });
  CLI::App* report = app.add_subcommand(
      "report", "a self-contained HTML page of a sweep: plots, the rows, the configuration");
  report->add_option("inputs", options->inputs, "sweep .jsonl or fps .csv files")
      ->required()
      ->check(CLI::ExistingFile);
  report->add_option("--out", options->report, "HTML file")->capture_default_str();
  report->callback([options] {
    std::vector<std::string> arguments = {"--out", options->report};
    arguments.insert(arguments.end(), options->inputs.begin(), options->inputs.end());
    runPlotScript("report", arguments);
  });
}

}  // namespace rtu
