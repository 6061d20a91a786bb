#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/output_paths.h"
#include "app/placement_flags.h"
#include "app/schema_flags.h"
#include "base/binary_file.h"
#include "base/output_file.h"
#include "explore/accel_build.h"
#include "kinds/registry.h"
#include "kinds/svo/svo_image.h"

namespace rtu {
namespace {

struct BuildOptions {
  std::string out;
  std::string stats;
  std::string trayRacerScene;
  bool modelHeader = false;
  ModelPlacement placement;
  glm::dvec3 rotationDegrees{0.0};
};

void buildSvo(const RunConfig& config, BuildOptions& options) {
  Scene scene = loadScene(config.scene);
  std::string headerReport;
  if (options.modelHeader) {
    options.placement.rotation = rotationFromEulerDegrees(options.rotationDegrees);
    headerReport = "model header at word " +
                   std::to_string(appendModelHeader(scene.image, options.placement)) + "\n";
  }
  writeSvoFile(options.out, scene.image);
  std::cout << scene.name << ": " << scene.summary << ", root at word " << scene.image.root << "\n"
            << headerReport << "wrote " << options.out << "\n";
}

std::string describe(const AccelQuality& q) {
  char text[256];
  std::snprintf(
      text, sizeof text,
      "%llu nodes, %llu leaves (%llu empty), depth %llu, %.2f triangles per leaf (at most "
      "%llu), SAH %.2f (seed's costs %.2f), %llu bytes, built in %.1f ms",
      static_cast<unsigned long long>(q.nodes), static_cast<unsigned long long>(q.leaves),
      static_cast<unsigned long long>(q.emptyLeaves), static_cast<unsigned long long>(q.depth),
      q.trianglesPerLeafMean, static_cast<unsigned long long>(q.trianglesPerLeafMax), q.sah,
      q.sahSeed, static_cast<unsigned long long>(q.bytes), 1e3 * q.buildSeconds);
  return text;
}

// The quality figures as JSON, with what was built from what.
void writeStats(const std::string& path, const RunConfig& config, const TriangleScene& scene,
                const AccelBuild& build) {
  nlohmann::json stats = build.quality;
  stats["accel"] = config.accel.structure;
  for (const auto& [key, value] : build.settings) stats[key] = value;
  stats["scene"] = scene.name;
  stats["dropped_triangles"] = scene.dropped.size();
  stats["dropped_triangle_ids"] = scene.dropped;
  writeTextFile(path, stats.dump(2) + "\n");
}

void writeByteFile(const std::string& path, const std::vector<uint8_t>& bytes) {
  writeTextFile(path, std::string(bytes.begin(), bytes.end()));
}

void buildTriangleStructure(const RunConfig& config, const BuildOptions& options) {
  const TriangleScene scene = loadSceneTriangles(config);
  const AccelBuild build = buildAccel(scene.mesh, config.accel, config.rtu);
  writeWordFile(options.out, build.words);
  if (!options.trayRacerScene.empty()) writeByteFile(options.trayRacerScene, build.sceneFile);
  if (!options.stats.empty()) writeStats(options.stats, config, scene, build);
  std::cout << scene.name << ": " << scene.mesh.triangles.size() << " triangles";
  if (!scene.dropped.empty())
    std::cout << " (" << scene.dropped.size() << " degenerate or duplicate dropped)";
  std::cout << "\n" << build.description << ": " << describe(build.quality) << "\n";
  for (const std::string& warning : build.warnings) std::cerr << "warning: " << warning << "\n";
  std::cout << "wrote " << options.out << "\n";
}

}  // namespace

void addBuildCommand(CLI::App& app) {
  auto options = std::make_shared<BuildOptions>();
  CLI::App* command = app.add_subcommand(
      "build",
      "build a memory image: an SVO (--accel svo) from a procedural scene, a mesh or a .binvox "
      "file, or a BVH, BIH or k-d tree (--accel bvh|bih|kdtree) over a mesh's triangles or a voxel "
      "scene's faces");
  auto request = addConfigOptions(*command, kUseScene | kUseAccel);
  command->add_option("--out", options->out, "output image (.svo, .bvh, .bih or .kd)")->required();
  command->add_option("--stats", options->stats,
                      "BVH, BIH or k-d tree: write the quality figures as JSON (nodes, leaves, "
                      "SAH, ...)");
  command->add_option("--trayracer-scene", options->trayRacerScene,
                      "k-d tree: also write the Tray Racer's own scene file (seed 001's format)");
  CLI::Option* header = command->add_flag(
      "--model-header", options->modelHeader,
      "SVO: append an animated model's header (16 words) after the image and print its word "
      "address");
  addPlacementOptions(*command, options->placement, options->rotationDegrees, header);
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    const RunConfig& config = configuration.values();
    checkOutputPaths({{"--out", options->out},
                      {"--stats", options->stats},
                      {"--trayracer-scene", options->trayRacerScene}},
                     inputPaths(config));
    if (!options->trayRacerScene.empty() && config.accel.structure != "kdtree")
      throw std::invalid_argument("--trayracer-scene: the Tray Racer's file holds a k-d tree "
                                  "(--accel kdtree)");
    if (config.accel.structure == "svo") {
      if (!options->stats.empty())
        throw std::invalid_argument(
            "--stats: quality figures are written for --accel bvh, bih or kdtree");
      buildSvo(config, *options);
    } else {
      if (options->modelHeader)
        throw std::invalid_argument("--model-header: only an SVO image (--accel svo) takes one");
      buildTriangleStructure(config, *options);
    }
  });
}

}  // namespace rtu
