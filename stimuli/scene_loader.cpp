#include "scene_loader.h"

#include <filesystem>
#include <memory>
#include <stdexcept>

#include "binvox.h"
#include "mesh_voxelizer.h"
#include "procedural_scenes.h"
#include "svo_builder.h"
#include "svo_validator.h"

namespace rtu {

namespace {

Scene sceneFromBuild(const SvoBuild& build, const std::string& name) {
  return Scene{build.image, name, build.stats.describe(), build.stats.depth};
}

std::string fileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

std::unique_ptr<VoxelSource> voxelSourceFor(const SceneSpec& spec, std::string& name) {
  if (!spec.meshFile.empty()) {
    name = fileName(spec.meshFile) + " (depth " + std::to_string(spec.depth) + ")";
    const TriangleMesh mesh = loadTriangleMesh(spec.meshFile);
    try {
      return std::make_unique<MeshVoxelizer>(mesh, spec.depth);
    } catch (const std::invalid_argument& error) {  // e.g. every vertex at one point
      throw std::invalid_argument("mesh '" + spec.meshFile + "': " + error.what());
    }
  }
  if (!spec.binvoxFile.empty()) {
    auto grid = std::make_unique<BinvoxGrid>(spec.binvoxFile);
    name = fileName(spec.binvoxFile) + " (" + std::to_string(grid->dim()) + "^3)";
    return grid;
  }
  name = spec.procedural + " (depth " + std::to_string(spec.depth) + ")";
  return makeProceduralScene(spec.procedural, spec.depth, spec.seed);
}

}  // namespace

Scene loadScene(const SceneSpec& spec) {
  const int files = !spec.svoFile.empty() + !spec.meshFile.empty() + !spec.binvoxFile.empty();
  if (files > 1)
    throw std::invalid_argument("give one scene: --svo, --mesh or --binvox, not several");
  if (!spec.svoFile.empty()) {
    SvoImage image = readSvoFile(spec.svoFile, spec.root);
    SvoReport report;
    try {
      report = validateSvo(image, SvoLimits{spec.maxDepth});
    } catch (const SvoFormatError& error) {
      throw std::runtime_error("SVO image '" + spec.svoFile + "' is malformed: " + error.what());
    }
    return Scene{std::move(image), fileName(spec.svoFile), describe(report), report.depth};
  }
  std::string name;
  const std::unique_ptr<VoxelSource> source = voxelSourceFor(spec, name);
  return sceneFromBuild(buildSvo(*source, spec.root), name);
}

}  // namespace rtu
