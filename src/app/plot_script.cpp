#include "app/plot_script.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "base/output_file.h"
#include "embedded_scripts.h"

extern char** environ;

namespace rtu {

namespace {

// Writes every embedded script (rtusim_plot.py and the modules it imports) into a new folder
// under /tmp and returns the folder.
std::string writeScripts() {
  char folder[] = "/tmp/rtusim_plot_XXXXXX";
  if (::mkdtemp(folder) == nullptr)
    throw std::runtime_error("cannot write the plotting script to /tmp");
  for (const auto& [name, text] : embeddedScripts())
    writeTextFile(std::string(folder) + "/" + name + ".py", text);
  return folder;
}

}  // namespace

std::vector<std::string> PlotArguments::arguments() const {
  std::vector<std::string> words;
  for (const auto& [option, value] : values)
    if (!value.empty()) words.insert(words.end(), {option, value});
  for (const auto& [option, values] : options)
    for (const std::string& value : values) words.insert(words.end(), {option, value});
  for (const auto& [flag, set] : flags)
    if (set) words.push_back(flag);
  // "--" ends the options: an input may start with '-'.
  words.push_back("--");
  words.insert(words.end(), inputs.begin(), inputs.end());
  return words;
}

void runPlotScript(const std::string& subcommand, const std::vector<std::string>& arguments) {
  const std::string folder = writeScripts();
  // Debian's python3 has python3-matplotlib; another python3 first on PATH may not.
  const char* python = ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
  std::vector<std::string> words = {python, folder + "/rtusim_plot.py", subcommand};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, python, nullptr, nullptr, argv.data(), environ);
  int status = 0;
  if (spawned == 0) ::waitpid(pid, &status, 0);
  std::error_code ignored;
  std::filesystem::remove_all(folder, ignored);
  if (spawned != 0)
    throw std::runtime_error("cannot run python3 for plots (install python3-matplotlib)");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("rtusim " + subcommand + " failed (see the message above)");
}

}  // namespace rtu
