#include "kinds/svo/scene_loader.h"

#include <filesystem>
#include <memory>
#include <stdexcept>

#include "base/work_phase.h"
#include "kinds/svo/binvox.h"
#include "kinds/svo/mesh_voxelizer.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_size_estimate.h"
#include "kinds/svo/svo_validator.h"
#include "kinds/svo/voxel_faces.h"
#include "rtu/host_memory.h"

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

// Refuses, before building, a root so far out that the image is mostly zeros and a tree that would
// not fit in this machine's memory (menger at depth 14 ran past 16 GB).
void checkBuildFits(const VoxelSource& source, const SceneSpec& spec, const std::string& name) {
  if (spec.root > kMaxBuildRoot)
    throw std::invalid_argument("--root " + std::to_string(spec.root) +
                                ": a built image would start with that many zero words; at most " +
                                std::to_string(kMaxBuildRoot) + " (256 MiB)");
  const SvoSizeEstimate size = estimateSvoSize(source, spec.root);
  if (size.imageBytes / 4 > 4294967296.0)
    throw std::runtime_error("building " + name + " would take about " +
                             std::to_string(static_cast<uint64_t>(size.imageBytes / 4)) +
                             " words, more than 32-bit word addresses reach: lower --depth");
  const uint64_t available = physicalMemoryBytes();
  if (size.peakBytes <= static_cast<double>(available)) return;
  throw std::runtime_error(
      "building " + name + " would need about " + formatGiB(size.peakBytes) +
      " of memory (estimated " + std::to_string(static_cast<uint64_t>(size.descriptors)) +
      " descriptors), more than the " + formatGiB(static_cast<double>(available)) +
      " of this machine: lower --depth");
}

}  // namespace

std::string sceneSource(const SceneSpec& scene) {
  if (!scene.svoFile.empty()) return "SVO image '" + scene.svoFile + "'";
  if (!scene.meshFile.empty()) return "mesh '" + scene.meshFile + "'";
  if (!scene.binvoxFile.empty()) return "binvox file '" + scene.binvoxFile + "'";
  return "scene '" + scene.procedural + "'";
}

Scene loadScene(const SceneSpec& spec) {
  const WorkPhase phase("loading the scene (" + sceneSource(spec) + ", --depth " +
                        std::to_string(spec.depth) + ")");
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
  checkBuildFits(*source, spec, name);
  return sceneFromBuild(buildSvo(*source, spec.root), name);
}

TriangleScene loadTriangleScene(const SceneSpec& spec, MeshDefectPolicy policy) {
  const int files = !spec.svoFile.empty() + !spec.meshFile.empty() + !spec.binvoxFile.empty();
  if (files > 1)
    throw std::invalid_argument("give one scene: --svo, --mesh or --binvox, not several");
  if (!spec.svoFile.empty())
    throw std::invalid_argument(
        "an .svo image holds no triangles: give --mesh, --binvox or --scene");
  TriangleScene scene;
  if (!spec.meshFile.empty()) {
    scene.name = fileName(spec.meshFile);
    scene.mesh = loadTriangleMesh(spec.meshFile);
    scene.dropped = checkTriangleMesh(scene.mesh, "mesh '" + spec.meshFile + "'", policy);
    return scene;
  }
  if (!spec.binvoxFile.empty()) {
    const BinvoxGrid grid(spec.binvoxFile);
    scene.name = fileName(spec.binvoxFile) + " (" + std::to_string(grid.dim()) + "^3, voxel faces)";
    scene.mesh = voxelFaces(grid);
  } else {
    scene.name = spec.procedural + " (depth " + std::to_string(spec.depth) + ", voxel faces)";
    scene.mesh = voxelFaces(*makeProceduralScene(spec.procedural, spec.depth, spec.seed));
  }
  if (scene.mesh.triangles.empty())
    throw std::invalid_argument(scene.name + " has no solid voxel: no triangles to build over");
  return scene;
}

}  // namespace rtu
