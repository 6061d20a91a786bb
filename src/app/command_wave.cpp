// rtusim wave t.fst: opens a trace in GTKWave with the save file written next to it.

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "app/commands.h"
#include "trace/gtkw_save_file.h"

namespace rtu {
namespace {

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream directories(path ? path : "");
  std::string directory;
  while (std::getline(directories, directory, ':'))
    if (!directory.empty() && access((directory + "/" + program).c_str(), X_OK) == 0) return true;
  return false;
}

bool hasDisplay() {
  for (const char* variable : {"DISPLAY", "WAYLAND_DISPLAY"}) {
    const char* value = std::getenv(variable);
    if (value && *value) return true;
  }
  return false;
}

}  // namespace

void addWaveCommand(CLI::App& app) {
  auto trace = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "wave", "open a trace (--trace t.fst) in GTKWave with its save file t.fst.gtkw");
  command->add_option("trace", *trace, "trace file (.fst or .vcd)")->required();
  command->callback([trace] {
    if (!std::filesystem::is_regular_file(*trace))
      throw std::invalid_argument("no such trace file: " + *trace);
    if (!onPath("gtkwave"))
      throw std::runtime_error("gtkwave not found on PATH: install the gtkwave package "
                               "(scripts/setup.sh)");
    if (!hasDisplay())
      throw std::runtime_error("no display to open GTKWave on (DISPLAY and WAYLAND_DISPLAY are "
                               "unset): run it under xvfb-run, or open " +
                               *trace + " with " + saveFilePath(*trace) +
                               " on a machine with a screen");
    std::string saveFile = saveFilePath(*trace);
    const bool withSaveFile = std::filesystem::is_regular_file(saveFile);
    char* arguments[] = {const_cast<char*>("gtkwave"), trace->data(),
                         withSaveFile ? saveFile.data() : nullptr, nullptr};
    execvp("gtkwave", arguments);
    throw std::runtime_error(std::string("cannot start gtkwave: ") + std::strerror(errno));
  });
}

}  // namespace rtu
