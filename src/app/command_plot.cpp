#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "app/commands.h"
#include "app/input_file_check.h"
#include "app/plot_script.h"

namespace rtu {
namespace {

// Options that gather every value given (repeatable), by flag and help text.
void addListOptions(CLI::App& command, PlotArguments& rows,
                    const std::vector<std::pair<std::string, std::string>>& options) {
  for (const auto& [flag, help] : options)
    command.add_option(flag, rows.options[flag], help)->allow_extra_args(false);
}

// --where and --label, which plot, report and best take alike.
void addRowOptions(CLI::App& command, PlotArguments& rows) {
  addListOptions(command, rows,
                 {{"--where", "keep only the rows with KEY=VALUE (repeatable; a schema key, "
                              "`preset` or `input`)"},
                  {"--label", "a name for each input, in their order, shown instead of the file "
                              "name"}});
}

// --objective, --group and --base of the best-configuration summary (report and best).
void addObjectiveOptions(CLI::App& command, PlotArguments& rows) {
  addListOptions(
      command, rows,
      {{"--objective", "STAT, max:STAT or min:STAT, a statistic or schema key (default fps; two "
                       "give the Pareto front)"},
       {"--group", "keys whose every value gets its own best row (default: the varied scene, "
                   "resolution, camera, workload and input)"},
       {"--base", "KEY=VALUE of the base configuration the gain is measured against (default: "
                  "the first row's values)"}});
}

}  // namespace

void addPlotCommands(CLI::App& app) {
  auto plotRows = std::make_shared<PlotArguments>();
  CLI::App* plot = app.add_subcommand(
      "plot",
      "plots (PNG and SVG) of sweep rows (.jsonl) or fps tables (.csv): frame rate against "
      "each varied key, or --y STAT against --x KEY, or against a resource with its Pareto front "
      "(--pareto); hit rates against cache size, core "
      "time, scheduler waits, cycles per ray against DRAM latency");
  plot->add_option("inputs", plotRows->inputs,
                   "sweep or fps .jsonl, fps .csv or --stats .json files")
      ->required()
      ->check(regularInputFile());
  plotRows->values["--out-dir"] = "plots";
  plot->add_option("--out-dir", plotRows->values["--out-dir"], "folder for the plots")
      ->capture_default_str();
  plot->add_option("--x", plotRows->values["--x"],
                   "the key on the x axis (default: each varied key)");
  plot->add_option("--y", plotRows->values["--y"],
                   "the statistic on the y axis, as `rtusim stats --list` names it or its JSON "
                   "path (memory.l1.hit_rate); default fps");
  plot->add_option("--by", plotRows->values["--by"],
                   "one line per value of this key (default: the next varied key; `none`: one "
                   "line per configuration of the other keys)");
  plot->add_option("--facet", plotRows->values["--facet"],
                   "one panel per value of this key (default: scene when it varies; `none`)");
  plot->add_option("--pareto", plotRows->values["--pareto"],
                   "only the Pareto front of --y (default fps) against this resource of the "
                   "rows' estimate: bram18k, dsp48e, memory_bits, bram_bits, multipliers, adders, "
                   "dividers, comparators, luts");
  addRowOptions(*plot, *plotRows);
  plot->callback([plotRows] { runPlotScript("plot", plotRows->arguments()); });

  auto reportRows = std::make_shared<PlotArguments>();
  CLI::App* report = app.add_subcommand(
      "report", "a self-contained HTML page of sweeps: the best configuration, plots, the rows "
                "(sortable), the configuration; two inputs are compared");
  report
      ->add_option("inputs", reportRows->inputs,
                   "sweep or fps .jsonl, fps .csv or --stats .json files")
      ->required()
      ->check(regularInputFile());
  reportRows->values["--out"] = "report.html";
  report->add_option("--out", reportRows->values["--out"], "HTML file")->capture_default_str();
  addRowOptions(*report, *reportRows);
  addObjectiveOptions(*report, *reportRows);
  report->callback([reportRows] { runPlotScript("report", reportRows->arguments()); });

  auto bestRows = std::make_shared<PlotArguments>();
  CLI::App* best = app.add_subcommand(
      "best", "the best configuration of sweep rows per group by an objective, its gain over the "
              "base configuration, and the Pareto front of two objectives");
  best->add_option("inputs", bestRows->inputs,
                   "sweep or fps .jsonl, fps .csv or --stats .json files")
      ->required()
      ->check(regularInputFile());
  addRowOptions(*best, *bestRows);
  addObjectiveOptions(*best, *bestRows);
  best->callback([bestRows] { runPlotScript("best", bestRows->arguments()); });
}

}  // namespace rtu
