#include "app/workers_option.h"

#include <iostream>

namespace rtu {

void addWorkersOption(CLI::App& command, int& workers, const std::string& help, int maxWorkers) {
  command.add_option("-j,--workers", workers, help)->check(CLI::Range(1, maxWorkers));
  const std::string warning = "rtusim: warning: " + command.get_name() +
                              " --jobs is deprecated: use -j/--workers (--jobs names a job-buffer "
                              "file in replay and golden)";
  command
      .add_option_function<int>(
          "--jobs",
          [&workers, warning](const int& count) {
            std::cerr << warning << "\n";
            workers = count;
          },
          "deprecated: as -j/--workers")
      ->check(CLI::Range(1, maxWorkers))
      ->group("Deprecated");
}

}  // namespace rtu
