#include <iomanip>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/kind_animation.h"
#include "explore/animation_run.h"
#include "explore/exploration_run.h"
#include "kind_app_plugins.h"
#include "kinds/registry.h"
#include "raypipe/raypipe_statistics.h"
#include "run/rtu_statistics.h"
#include "run/sampled_run.h"
#include "run/statistics_output.h"

namespace rtu {
namespace {

// Every statistic rtusim writes, from the declarations (base/statistics.h), grouped by output.
void listAllStatistics(std::ostream& out) {
  listStatistics(out, "# " + RtuStatistics::declaration().title(),
                 RtuStatistics::declaration().statistics());
  std::vector<Statistic> sample;
  SampledRun::declaration().describe(sample, "sample/");
  out << "\n";
  listStatistics(out,
                 "# " + SampledRun::declaration().title() +
                     ": \"sample\" in the statistics of fps and sweep rows with --sample",
                 sample);
  out << "\n";
  listStatistics(out, "# " + FrameStatistics::declaration().title(),
                 FrameStatistics::declaration().statistics());
  out << "\n";
  forEachCoreKind([&out](auto kind) {
    using Animation = KindAnimation<decltype(kind)>;
    if constexpr (Animation::kAnimates) {
      Animation::listStatistics(out);
      out << "\n";
    }
  });
  listStatistics(out, "# " + RaypipeStatistics::declaration().title(),
                 RaypipeStatistics::declaration().statistics());
  out << "\n# the statistics columns of fps --csv and sweep --out (CSV)\n"
      << std::left << std::setw(28) << "column"
      << "key\n";
  for (const auto& [column, key] : statisticsColumnKeys())
    out << std::setw(28) << column << key << "\n";
}

}  // namespace

void addStatsCommand(CLI::App& app) {
  auto list = std::make_shared<bool>(false);
  CLI::App* command = app.add_subcommand(
      "stats", "show every statistic rtusim writes (--list): its key in the JSON, unit, "
               "how it combines over cores, frames and rows, and what it counts");
  command->add_flag("--list", *list, "every statistic with its key, unit, combination and doc");
  command->callback([list] {
    if (!*list) throw std::invalid_argument("give --list");
    listAllStatistics(std::cout);
  });
}

}  // namespace rtu
