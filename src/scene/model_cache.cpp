#include "scene/model_cache.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "base/binary_file.h"
#include "base/input_file.h"

namespace rtu {

namespace {

constexpr uint64_t kFnvOffset = 0xcbf29ce484222325ull;
constexpr uint64_t kFnvPrime = 0x100000001b3ull;

uint64_t fnv1a(uint64_t hash, const std::string& bytes) {
  for (const char byte : bytes) hash = (hash ^ static_cast<unsigned char>(byte)) * kFnvPrime;
  return hash;
}

// The model's file is hashed whole; the scene file checked it is a regular file, and it is
// bounded like an image (a file beyond that could not be built).
std::string fileContents(const std::string& path) {
  return readInputFile(path, "model", kMaxImageWords * sizeof(uint32_t));
}

// What decides the built image; the format version changes when the builders' output does.
std::string description(const SceneSpec& source) {
  std::string text = "rtusim model 1\ndepth " + std::to_string(source.depth) + "\n";
  if (!source.meshFile.empty()) return text + "mesh\n" + fileContents(source.meshFile);
  if (!source.binvoxFile.empty()) return text + "binvox\n" + fileContents(source.binvoxFile);
  return text + "procedural " + source.procedural + " seed " + std::to_string(source.seed) + "\n";
}

bool cacheable(const SceneSpec& source) { return source.svoFile.empty(); }

// Written beside its final name and renamed, so a reader never sees half a file.
void storeInCache(const SvoImage& image, const std::filesystem::path& file) {
  std::filesystem::create_directories(file.parent_path());
  const std::filesystem::path partial =
      file.string() + ".partial-" + std::to_string(static_cast<long>(getpid()));
  writeSvoFile(partial.string(), image);
  std::filesystem::rename(partial, file);
}

Scene buildOrRead(const ModelDescription& model, const std::string& cacheDirectory,
                  bool& fromCache) {
  fromCache = false;
  if (!cacheable(model.source)) return loadScene(model.source);
  const std::filesystem::path file =
      std::filesystem::path(cacheDirectory) / (modelCacheKey(model) + ".svo");
  if (std::filesystem::exists(file)) {
    SceneSpec cached;
    cached.svoFile = file.string();
    Scene scene = loadScene(cached);
    scene.name = model.name + " (cached " + file.filename().string() + ")";
    fromCache = true;
    return scene;
  }
  Scene scene = loadScene(model.source);
  storeInCache(scene.image, file);
  return scene;
}

}  // namespace

std::string modelCacheKey(const ModelDescription& model) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(fnv1a(kFnvOffset, description(model.source))));
  return hex;
}

SceneModel loadSceneModel(const ModelDescription& model, const std::string& cacheDirectory) {
  SceneModel loaded{model.name, {}, {}, false};
  try {
    loaded.scene = buildOrRead(model, cacheDirectory, loaded.fromCache);
  } catch (const std::exception& error) {
    throw std::runtime_error("model '" + model.name + "': " + error.what());
  }
  loaded.bounds = solidVoxelBounds(loaded.scene.image);
  if (loaded.bounds.empty)
    throw std::runtime_error("model '" + model.name + "' has no solid voxel");
  return loaded;
}

std::string defaultModelCacheDirectory() {
  if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache && *cache)
    return std::string(cache) + "/rtusim/models";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::string(home) + "/.cache/rtusim/models";
  return ".rtusim-cache";
}

}  // namespace rtu
