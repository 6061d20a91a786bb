#include "app/plot_script.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "embedded_scripts.h"

extern char** environ;

namespace rtu {

void runPlotScript(const std::string& subcommand, const std::vector<std::string>& arguments) {
  char scriptPath[] = "/tmp/rtusim_plot_XXXXXX";
  const int fd = ::mkstemp(scriptPath);
  if (fd < 0) throw std::runtime_error("cannot write the plotting script to /tmp");
  ::close(fd);
  {
    std::ofstream script(scriptPath);
    script << embeddedScripts().at("rtusim_plot");
  }
  // Debian's python3 has python3-matplotlib; another python3 first on PATH may not.
  const char* python = ::access("/usr/bin/python3", X_OK) == 0 ? "/usr/bin/python3" : "python3";
  std::vector<std::string> words = {python, scriptPath, subcommand};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, python, nullptr, nullptr, argv.data(), environ);
  int status = 0;
  if (spawned == 0) ::waitpid(pid, &status, 0);
  ::unlink(scriptPath);
  if (spawned != 0)
    throw std::runtime_error("cannot run python3 for plots (install python3-matplotlib)");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("rtusim " + subcommand + " failed (see the message above)");
}

}  // namespace rtu
