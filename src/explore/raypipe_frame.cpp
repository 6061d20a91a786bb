#include "explore/raypipe_frame.h"

#include <chrono>
#include <cstring>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "base/binary_file.h"
#include "explore/accel_build.h"
#include "kinds/kd/kd_image.h"
#include "reference/raypipe_cycles.h"
#include "sim/raypipe/raypipe_timed.h"

namespace rtu {
namespace {

RaypipeScene builtScene(const RunConfig& settings) {
  TriangleScene triangles = loadSceneTriangles(settings);
  AccelSpec spec = settings.accel;
  spec.structure = "kdtree";
  const AccelBuild build = buildAccel(triangles.mesh, spec);
  const TrayRacerFormat format = spec.index == "wide" ? TrayRacerFormat::Wide
                                                      : TrayRacerFormat::Narrow;
  RaypipeScene scene;
  scene.name = triangles.name;
  scene.description =
      build.description + ", " + std::to_string(triangles.mesh.triangles.size()) + " triangles";
  // Read back from the file, as the hardware loads it: a narrow file's splits keep 28 bits.
  scene.image = layOutKd(readTrayRacerScene(build.sceneFile, format)).words;
  for (const auto& triangle : triangles.mesh.triangles) {
    const glm::dvec3& a = triangles.mesh.vertices[triangle[0]];
    scene.normals.push_back(glm::cross(triangles.mesh.vertices[triangle[1]] - a,
                                       triangles.mesh.vertices[triangle[2]] - a));
  }
  scene.warnings = build.warnings;
  return scene;
}

void checkImage(const std::vector<uint32_t>& words, const std::string& path) {
  const std::vector<ImageProblem> problems = validateKd(words);
  if (!problems.empty())
    throw std::runtime_error(
        path + ": not a sound k-d scene: " + problems.front().what +
        (problems.size() > 1 ? " (and more: rtusim validate lists them)" : ""));
}

// A k-d image (its magic first), which holds no normals, or the seed's scene file (big-endian
// words), whose colour section does (vertex 0's).
RaypipeScene sceneFromFile(const std::string& path, const RunConfig& settings) {
  std::vector<uint32_t> words = readWordFile(path, sizeof(uint32_t), "k-d image or scene file");
  RaypipeScene scene;
  scene.name = path;
  if (!words.empty() && words[0] == kKdMagic) {
    checkImage(words, path);
    const KdHeader header = decodeKdHeader(words.data());
    scene.description = "k-d image, " + std::to_string(header.uttmCount) + " triangles";
    scene.image = std::move(words);
    return scene;
  }
  const bool wide = settings.accel.index == "wide";
  std::vector<uint8_t> bytes(words.size() * sizeof(uint32_t));
  std::memcpy(bytes.data(), words.data(), bytes.size());
  const TrayRacerScene file =
      readTrayRacerScene(bytes, wide ? TrayRacerFormat::Wide : TrayRacerFormat::Narrow);
  scene.description = std::string("the Tray Racer's scene file (") + (wide ? "wide" : "narrow") +
                      "), " + std::to_string(file.uttms.size()) + " triangles";
  scene.image = layOutKd(file).words;
  checkImage(scene.image, path);  // a child or a list entry out of range
  for (const TrayRacerShade& shade : file.shades) scene.normals.push_back(trayRacerNormal(shade));
  scene.warnings = trayRacerCapacityWarnings(file);
  return scene;
}

std::vector<RaypipeCycleRay> cycleRays(const std::vector<PrimaryRay>& rays) {
  std::vector<RaypipeCycleRay> input;
  input.reserve(rays.size());
  for (const PrimaryRay& ray : rays) input.push_back({ray.ray, ray.pixel.pixelId});
  return input;
}

RaypipeCycleOptions cycleOptions(const RaypipeConfig& config) {
  RaypipeCycleOptions options;
  options.writer = {config.vgaWindow, config.vgaPhase};
  return options;
}

}  // namespace

RaypipeScene loadRaypipeScene(const RunConfig& settings, const std::string& sceneFile) {
  return sceneFile.empty() ? builtScene(settings) : sceneFromFile(sceneFile, settings);
}

PrgFrameSize raypipeFrameSize(const RunConfig& settings) {
  const int level = settings.raypipeView.level;
  return level >= 0 ? prgLevelSize(level)
                    : PrgFrameSize{settings.camera.width, settings.camera.height};
}

std::vector<PrimaryRay> raypipeFrameRays(const RunConfig& settings) {
  return primaryRays(settings.raypipeView.camera.resolve(settings.camera),
                     raypipeFrameSize(settings));
}

RaypipeCycleRun runRaypipeFrame(const RaypipeConfig& config, const std::vector<uint32_t>& image,
                                const std::vector<PrimaryRay>& rays, CycleTrace* trace) {
  config.validate();
  return runRaypipeTimed(config, KdImage{image}, cycleRays(rays), cycleOptions(config), trace);
}

RaypipeCycleRun runRaypipeReferenceFrame(const RaypipeConfig& config,
                                         const std::vector<uint32_t>& image,
                                         const std::vector<PrimaryRay>& rays) {
  config.validate();
  const std::vector<RaypipeCycleRay> input = cycleRays(rays);
  const auto start = std::chrono::steady_clock::now();
  RaypipeCycleRun run = runRaypipeCycles(config, KdImage{image}, input, cycleOptions(config));
  run.hostSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace rtu
