#include "base/plugin_loader.h"

#include <dlfcn.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <vector>

// Where the build writes the modules; set by stimuli/CMakeLists.txt.
#ifndef RTUSIM_PLUGIN_BUILD_DIR
#define RTUSIM_PLUGIN_BUILD_DIR ""
#endif

namespace rtu {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> searchDirectories() {
  std::vector<fs::path> directories;
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) directories.push_back(executable.parent_path());
  const fs::path built(RTUSIM_PLUGIN_BUILD_DIR);
  if (!built.empty() && (directories.empty() || !fs::equivalent(built, directories[0], error)))
    directories.push_back(built);
  return directories;
}

void* openModule(const std::string& file, const std::string& purpose) {
  const std::vector<fs::path> directories = searchDirectories();
  std::string searched;
  for (const fs::path& directory : directories) {
    const fs::path candidate = directory / file;
    searched += (searched.empty() ? "" : ", ") + directory.string();
    std::error_code error;
    if (!fs::exists(candidate, error)) continue;
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr)
      throw std::runtime_error("cannot load " + candidate.string() + " (" + purpose +
                               "): " + dlerror());
    using AbiFunction = int();
    auto* abi = reinterpret_cast<AbiFunction*>(dlsym(handle, "rtusim_plugin_abi"));
    if (abi == nullptr || abi() != kPluginAbi) {
      dlclose(handle);
      throw std::runtime_error(candidate.string() + " (" + purpose +
                               ") was built for another version of rtusim: rebuild it");
    }
    return handle;
  }
  throw std::runtime_error("cannot find " + file + " (" + purpose + ") in " +
                           (searched.empty() ? std::string("any directory") : searched) +
                           ": build it with the rtusim target and keep it next to the rtusim "
                           "binary");
}

}  // namespace

void* pluginSymbol(const std::string& file, const char* symbol, const std::string& purpose) {
  static std::mutex mutex;
  static std::map<std::string, void*> handles;
  const std::lock_guard<std::mutex> lock(mutex);
  void*& handle = handles[file];
  if (handle == nullptr) handle = openModule(file, purpose);
  void* address = dlsym(handle, symbol);
  if (address == nullptr)
    throw std::runtime_error(file + " (" + purpose + ") lacks the entry point " + symbol +
                             ": rebuild it");
  return address;
}

}  // namespace rtu
