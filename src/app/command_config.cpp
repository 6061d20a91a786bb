#include <iomanip>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/schema_flags.h"

namespace rtu {
namespace {

constexpr unsigned kAllUses = kUseModel | kUseModelChoice | kUseArithmetic | kUseScene |
                              kUseCamera | kUseBuffers | kUseSampling;

void listSettings(std::ostream& out) {
  const RunConfig defaults;
  out << std::left << std::setw(28) << "key" << std::setw(28) << "flag" << std::setw(12)
      << "default" << std::setw(22) << "range"
      << "unit: doc\n";
  for (const Setting& s : configSchema()) {
    const std::string value = s.get(defaults);
    out << std::setw(28) << s.key << std::setw(28) << (s.flag.empty() ? "-" : s.flag)
        << std::setw(12) << (value.empty() ? "\"\"" : value) << std::setw(22) << s.range()
        << (s.unit.empty() ? "" : s.unit + ": ") << s.doc
        << (s.formerFlag.empty() ? "" : " (old spelling " + s.formerFlag + ")") << "\n";
  }
}

}  // namespace

void addConfigCommand(CLI::App& app) {
  struct Options {
    bool dump = false, list = false, json = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "config", "show the configuration schema (--list) or the effective configuration of a "
                "preset, files and settings (--dump), in a form --config loads again");
  auto request = addConfigOptions(*command, kAllUses);
  command->add_flag("--list", options->list, "every key with its flag, default, range and doc");
  command->add_flag("--dump", options->dump, "the effective configuration as TOML");
  command->add_flag("--json", options->json, "with --dump: as JSON instead");
  command->callback([options, request] {
    if (options->list == options->dump) throw std::invalid_argument("give --list or --dump");
    if (options->list) return listSettings(std::cout);
    const Configuration configuration = request->resolve();
    if (options->json)
      std::cout << configuration.toJson().dump(2) << "\n";
    else
      std::cout << configuration.toToml();
  });
}

}  // namespace rtu
