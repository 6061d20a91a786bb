#include "app/output_paths.h"

#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace rtu {
namespace {

namespace fs = std::filesystem;

std::string named(const NamedPath& file) { return file.option + " '" + file.path + "'"; }

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error, errorA, errorB;
  if (fs::equivalent(a, b, error)) return true;  // both exist: links and spellings resolved
  const fs::path canonicalA = fs::weakly_canonical(a, errorA);
  const fs::path canonicalB = fs::weakly_canonical(b, errorB);
  return !errorA && !errorB && canonicalA == canonicalB;
}

void checkWritable(const NamedPath& output) {
  fs::path path(output.path);
  std::error_code error;
  if (fs::is_directory(path, error))
    throw std::invalid_argument(named(output) + " is a directory, not a file");
  if (fs::exists(path, error)) {
    if (access(path.c_str(), W_OK) != 0)
      throw std::invalid_argument(named(output) + " exists and cannot be written");
    if (!fs::is_regular_file(path, error)) return;  // a device or a pipe is written in place
    path = fs::canonical(path, error);  // a file is replaced by one written beside it (OutputFile)
  }
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, error))
    throw std::invalid_argument(named(output) + ": folder '" + parent.string() +
                                "' does not exist");
  if (access(parent.c_str(), W_OK) != 0)
    throw std::invalid_argument(named(output) + ": folder '" + parent.string() +
                                "' cannot be written");
}

}  // namespace

std::vector<NamedPath> inputPaths(const RunConfig& settings) {
  return {{"--svo", settings.scene.svoFile},   {"--accel-file", settings.accel.file},
          {"--mesh", settings.scene.meshFile}, {"--binvox", settings.scene.binvoxFile},
          {"--jobs", settings.jobs},           {"--rays", settings.rays}};
}

void checkOutputPaths(const std::vector<NamedPath>& outputs, const std::vector<NamedPath>& inputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedPath& output = outputs[i];
    if (output.path.empty()) continue;
    for (const NamedPath& input : inputs)
      if (!input.path.empty() && sameFile(output.path, input.path))
        throw std::invalid_argument(named(output) + " is the input " + named(input) +
                                    ": writing it would destroy the input");
    for (size_t j = 0; j < i; ++j)
      if (!outputs[j].path.empty() && sameFile(output.path, outputs[j].path))
        throw std::invalid_argument(named(output) + " and " + named(outputs[j]) + " are one file");
    checkWritable(output);
  }
}

std::string jsonLinesPath(const std::string& csvPath) {
  return std::filesystem::path(csvPath).replace_extension(".jsonl").string();
}

void createOutputFolder(const NamedPath& folder) {
  std::error_code error;
  fs::create_directories(folder.path, error);
  if (error || !fs::is_directory(folder.path))
    throw std::invalid_argument(named(folder) + ": cannot create the folder" +
                                (error ? ": " + error.message() : std::string(": it is a file")));
}

}  // namespace rtu
