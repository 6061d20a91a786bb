#include <memory>

#include "app/commands.h"
#include "app/input_file_check.h"
#include "app/plot_script.h"

namespace rtu {

void addDiffCommand(CLI::App& app) {
  auto diff = std::make_shared<PlotArguments>();
  CLI::App* command = app.add_subcommand(
      "diff", "two statistics files (--stats .json) or two sweeps (.jsonl) side by side: the "
              "configuration differences first, then every statistic with difference and ratio");
  command->add_option("inputs", diff->inputs, "A and B: two .json or two .jsonl files")
      ->required()
      ->expected(2)
      ->check(regularInputFile());
  command
      ->add_option("--stat", diff->options["--stat"],
                   "only these statistics (repeatable; a JSON path such as fps or "
                   "memory.l1.hit_rate, or its start: memory.l1)")
      ->allow_extra_args(false);
  command->add_flag("--changed", diff->flags["--changed"], "only the statistics that differ");
  command->add_option("--label", diff->options["--label"], "names for A and B")
      ->expected(0, 2)
      ->allow_extra_args(false);
  command->callback([diff] { runPlotScript("diff", diff->arguments()); });
}

}  // namespace rtu
