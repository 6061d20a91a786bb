// `rtusim compare` (issue 30): one scene and camera on every architecture, side by side. The
// scene's triangles (a mesh, a voxel scene's faces, or a scene file's frame flattened into one
// mesh: explore/scene_mesh.h) are traced by the triangle kinds and the ray pipe, and voxelized
// for the SVO at the depth where a voxel is no wider than a pixel's footprint (or --depth); every
// architecture's row is the fps row of its configuration (compare_row.h), run in worker processes
// with a progress line, and its image is measured against the float64 reference over the same
// triangles (explore/reference_frame.h). docs/comparison.md.

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "app/commands.h"
#include "app/compare_row.h"
#include "app/output_paths.h"
#include "app/plot_script.h"
#include "app/schema_flags.h"
#include "app/workers_option.h"
#include "base/output_file.h"
#include "config/sweep_spec.h"
#include "explore/accel_build.h"
#include "explore/exploration_run.h"
#include "explore/frame_scene.h"
#include "explore/reference_frame.h"
#include "explore/scene_mesh.h"
#include "explore/sweep_workers.h"
#include "kinds/svo/voxel_faces.h"
#include "scene/model_cache.h"

namespace rtu {
namespace {

using Json = nlohmann::ordered_json;

constexpr const char* kRaypipe = "raypipe";
// Every architecture: the RTU with each core kind, then the ray pipe.
std::vector<std::string> allArchitectures() {
  std::vector<std::string> names = CoreKinds::names();
  names.push_back(kRaypipe);
  return names;
}
// The preset of the RTU's kinds unless --preset or NAME=PRESET says otherwise: the common one of
// issue 30 (16 cores, BRAM caches, DRAM behind them).
constexpr const char* kCommonPreset = "cached";
// The deepest octree the footprint rule chooses: the thesis stack's 11 frames traverse depth 12.
constexpr int kMaxFootprintDepth = 12;

struct CompareOptions {
  std::vector<std::string> architectures = allArchitectures();
  std::string sceneFile, csv, json, html, images;
  std::string cacheDir = defaultModelCacheDirectory();
  int workers = defaultWorkerCount();
};

struct ArchitectureChoice {
  std::string name, preset;  // preset "": the default
};

std::string knownArchitectures() {
  std::string names;
  for (const std::string& kind : CoreKinds::names()) names += kind + ", ";
  return names + kRaypipe;
}

// "bvh" or "bih=fixedpoint"; unknown names and presets, and repeats, are errors naming them.
std::vector<ArchitectureChoice> parseArchitectures(const std::vector<std::string>& list) {
  std::vector<ArchitectureChoice> choices;
  std::set<std::string> seen;
  const std::vector<std::string> kinds = CoreKinds::names();
  for (const std::string& item : list) {
    const size_t equals = item.find('=');
    ArchitectureChoice choice{item.substr(0, equals),
                              equals == std::string::npos ? "" : item.substr(equals + 1)};
    if (choice.name != kRaypipe &&
        std::find(kinds.begin(), kinds.end(), choice.name) == kinds.end())
      throw std::invalid_argument("--architectures: no architecture '" + choice.name + "' (" +
                                  knownArchitectures() + ")");
    if (!seen.insert(choice.name).second)
      throw std::invalid_argument("--architectures: " + choice.name + " is given twice");
    if (!choice.preset.empty()) presetText(choice.preset);  // throws naming the presets
    choices.push_back(choice);
  }
  if (choices.empty()) throw std::invalid_argument("--architectures: give at least one");
  return choices;
}

// The shallowest depth (from 2, the voxelizer's least) whose voxels, 2 / 2^depth wide in the
// cube, are no wider than `footprint`; at most kMaxFootprintDepth.
int footprintDepth(double footprint) {
  for (int depth = 2; depth < kMaxFootprintDepth; ++depth)
    if (2 / std::ldexp(1.0, depth) <= footprint) return depth;
  return kMaxFootprintDepth;
}

bool givenByCommand(const Configuration& configuration, const std::string& key) {
  const ConfigSource source = configuration.source(key);
  return source == ConfigSource::CommandLine || source == ConfigSource::File;
}

// A point of the model's space in the world, and back (the placement's scale is uniform, as a
// mesh's fit into the cube is).
glm::dvec3 placed(const ModelPlacement& placement, const glm::dvec3& p) {
  return placement.translation + placement.rotation * (placement.scale * p);
}
glm::dvec3 unplaced(const ModelPlacement& placement, const glm::dvec3& p) {
  return glm::transpose(placement.rotation) * (p - placement.translation) / placement.scale;
}

// The camera moved as `move` moves points, its up vector turned with them.
Camera movedCamera(const Camera& camera, const std::function<glm::dvec3(const glm::dvec3&)>& move) {
  Camera moved = camera;
  moved.position = move(camera.position);
  moved.lookAt = move(camera.lookAt);
  moved.up = move(camera.position + camera.up) - moved.position;
  return moved;
}

// What every architecture shares: the settings of the scene (the depth, the scene file's mesh and
// size), the camera in the cube, the reference and the ray pipe's move into a mesh's own space.
struct SharedFrame {
  std::vector<std::pair<std::string, std::string>> sets;  // key, value
  std::optional<Camera> sceneCamera;                      // a scene file's, in its world
  ModelPlacement placement;
  std::optional<ReferenceTracer> tracer;
  std::vector<std::optional<OracleHit>> reference;
  std::string triangles;  // the scene's triangles, for the heading
};

// A scene file's first frame as one mesh, written to `folder`; its camera and size.
void flattenSceneFile(const std::string& path, const std::string& folder, Configuration& base,
                      SharedFrame& shared) {
  const SceneMesh scene = sceneMesh(readSceneFile(path), 0.0);
  const std::string mesh = folder + "/scene.obj";
  writeObjMesh(mesh, scene.mesh);
  shared.sets.push_back({"mesh", mesh});
  for (const auto& [key, value] :
       {std::pair<std::string, int>{"width", scene.camera.width}, {"height", scene.camera.height}})
    if (!givenByCommand(base, key)) shared.sets.push_back({key, std::to_string(value)});
  for (const auto& [key, value] : shared.sets) base.set(key, value, ConfigSource::Preset);
  // Dropped rather than refused: the models' own meshes were checked so already.
  base.values().accel.dropBadTriangles = true;
  shared.sceneCamera = scene.camera;
  shared.sceneCamera->width = base.values().camera.width;
  shared.sceneCamera->height = base.values().camera.height;
}

// A scene file's frame voxelized at `depth` for the SVO, kept in the model cache of `rtusim
// animate` (scene/model_cache.h, --cache-dir: named by a hash of the flattened mesh and the
// depth), so the next compare of the same frame reads it back instead of voxelizing it again; its
// path.
std::string cachedFrameSvo(const std::string& mesh, int depth, const std::string& directory) {
  ModelDescription frame{"frame 0", {}};
  frame.source.meshFile = mesh;
  frame.source.depth = depth;
  const std::string path = directory + "/" + modelCacheKey(frame) + ".svo";
  const auto start = std::chrono::steady_clock::now();
  const SceneModel model = loadSceneModel(frame, directory);
  std::cout << "compare: the SVO of frame 0 at depth " << depth << " "
            << (model.fromCache ? "read from " : "built and cached in ") << path << " ("
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s)\n";
  return path;
}

// The frame's camera at `depth`: a scene file's moves with its mesh into the cube.
Camera frameCamera(const RunConfig& settings, const SharedFrame& shared, const TriangleMesh& mesh,
                   int depth) {
  if (!shared.sceneCamera) return settings.camera;
  SceneSpec spec = settings.scene;
  spec.depth = depth;
  const ModelPlacement fit = framePlacement(spec, mesh);
  return movedCamera(*shared.sceneCamera, [&](const glm::dvec3& p) { return placed(fit, p); });
}

// A pixel's footprint at the nearest point of the mesh the frame sees, with the mesh fitted into
// the cube at `depth`: 2 t tan(fov / 2) / height at the nearest hit's distance t; 0 when the frame
// sees none of it.
double nearestFootprint(const RunConfig& settings, const SharedFrame& shared,
                        const TriangleMesh& mesh, int depth) {
  SceneSpec spec = settings.scene;
  spec.depth = depth;
  const Camera camera = frameCamera(settings, shared, mesh, depth);
  const ReferenceTracer tracer(placedMesh(mesh, framePlacement(spec, mesh)));
  double nearest = INFINITY;
  for (const std::optional<OracleHit>& hit : referenceFrame(tracer, camera))
    if (hit) nearest = std::min(nearest, hit->t);
  if (std::isinf(nearest)) return 0;
  return 2 * nearest * std::tan(camera.verticalFovDegrees * M_PI / 360) / camera.height;
}

// The depth: --depth, or for a mesh the footprint's at the nearest point the frame sees; a voxel
// scene's faces go to depth 9.
int chooseDepth(const Configuration& base, const SharedFrame& shared, const TriangleMesh& mesh,
                const std::vector<ArchitectureChoice>& choices) {
  const RunConfig& settings = base.values();
  if (settings.scene.meshFile.empty() || givenByCommand(base, "scene.depth")) {
    const bool triangles = std::any_of(choices.begin(), choices.end(),
                                       [](const ArchitectureChoice& c) { return c.name != "svo"; });
    if (settings.scene.meshFile.empty() && triangles && settings.scene.depth > kMaxVoxelFaceDepth)
      throw std::invalid_argument("--depth " + std::to_string(settings.scene.depth) +
                                  ": the triangle architectures trace the voxel scene's faces, "
                                  "built to depth " +
                                  std::to_string(kMaxVoxelFaceDepth) + " at most");
    return settings.scene.depth;
  }
  // The fit into the cube moves the mesh by less than a voxel from one depth to the next, so the
  // nearest point is found once, at depth 8.
  const double footprint = nearestFootprint(settings, shared, mesh, 8);
  return footprint > 0 ? footprintDepth(footprint) : settings.scene.depth;
}

// The float64 reference over the scene's triangles where the frame places them.
void traceReference(const RunConfig& settings, const TriangleScene& triangles,
                    SharedFrame& shared) {
  shared.placement = framePlacement(settings.scene, triangles.mesh);
  shared.triangles =
      triangles.name + ", " + std::to_string(triangles.mesh.triangles.size()) + " triangles";
  shared.tracer.emplace(placedMesh(triangles.mesh, shared.placement));
  shared.reference = referenceFrame(*shared.tracer, settings.camera);
}

CompareTarget makeTarget(const ConfigRequest& request, const ArchitectureChoice& choice,
                         const SharedFrame& shared, const Camera& camera,
                         const std::string& images) {
  ConfigRequest own = request;
  const bool raypipe = choice.name == kRaypipe;
  // The ray pipe's settings default to the seed's final build; its preset would set the camera.
  own.preset = !choice.preset.empty()   ? choice.preset
               : raypipe                ? ""
               : request.preset.empty() ? kCommonPreset
                                        : request.preset;
  CompareTarget target{choice.name, own.preset, own.resolveUnchecked(), {}, {}};
  Configuration& configuration = target.configuration;
  // What compare sets counts as a preset's: not the user's, so never reported as without effect.
  for (const auto& [key, value] : shared.sets) configuration.set(key, value, ConfigSource::Preset);
  configuration.set(raypipe ? "architecture" : "core", raypipe ? kRaypipe : choice.name,
                    ConfigSource::Preset);
  // The seeds' index widths hold small scenes only (the BIH 1,024 nodes, the Tray Racer's narrow
  // scene file 2^16): the wide ones, unless given.
  if (!givenByCommand(configuration, "accel.index"))
    configuration.set("accel.index", "wide", ConfigSource::Preset);
  // Secondary passes (workload.rays) spawn from a core kind's hits: the ray pipe traces the frame.
  if (raypipe) configuration.set("workload.rays", "primary", ConfigSource::Preset);
  configuration.values().camera = camera;
  if (!images.empty()) target.differenceImage = images + "/" + choice.name + ".png";
  return target;
}

// The ray pipe traces a mesh where it lies, not fitted into the cube: its camera moves into the
// mesh's space, and its distances back by the fit's scale.
void moveRaypipeCamera(CompareTarget& target, const ModelPlacement& fit) {
  Camera& camera = target.configuration.values().camera;
  camera = movedCamera(camera, [&](const glm::dvec3& p) { return unplaced(fit, p); });
  target.raypipePlacement = fit;
}

std::string cell(const Json& value, int precision) {
  if (value.is_null()) return "-";
  if (value.is_string()) return value.get<std::string>();
  std::ostringstream text;
  text << std::fixed << std::setprecision(value.is_number_integer() ? 0 : precision)
       << value.get<double>();
  return text.str();
}

void printTable(const std::vector<Json>& rows, std::ostream& out) {
  const std::vector<std::pair<std::string, std::string>> columns = {
      {"image_bytes", "bytes"},         {"build_seconds", "build s"},
      {"total_cycles", "cycles"},       {"fps", "fps"},
      {"cycles_per_ray", "cyc/ray"},    {"core_bytes_per_ray", "B/ray core"},
      {"l2_bytes_per_ray", "B/ray L2"}, {"dram_bytes_per_ray", "B/ray DRAM"},
      {"l1_hit_rate", "L1 hit"},        {"l2_hit_rate", "L2 hit"},
      {"nodes_per_ray", "nodes/ray"},   {"tests_per_ray", "tests/ray"},
      {"utilisation", "util"},          {"limit", "limit"},
      {"bram18k", "BRAM18k"},           {"dsp48e", "DSP48E"},
      {"fps_per_bram18k", "fps/BRAM"},  {"fps_per_dsp48e", "fps/DSP"},
      {"hit_miss_differ", "hit/miss"},  {"other_object", "other obj"},
      {"mean_depth_error", "depth err"}};
  // A space before every cell, so a long limit name ("dram_bandwidth") never runs into the cell
  // before it.
  const auto width = [](const std::string& key) { return key == "limit" ? 14 : 11; };
  out << std::left << std::setw(9) << "arch";
  for (const auto& [key, title] : columns)
    out << ' ' << std::right << std::setw(width(key)) << title;
  out << "\n";
  for (const Json& row : rows) {
    out << std::left << std::setw(9) << row["architecture"].get<std::string>();
    if (row["status"] != "ok") {
      out << "failed: " << row["error"].get<std::string>() << "\n";
      continue;
    }
    for (const auto& [key, title] : columns) {
      const Json& value = row.contains(key)              ? row[key]
                          : row["figures"].contains(key) ? row["figures"][key]
                                                         : row["agreement"][key];
      out << ' ' << std::right << std::setw(width(key))
          << cell(value, key == "mean_depth_error" ? 5 : 2);
    }
    out << "\n";
  }
}

void writeOutputs(const std::vector<Json>& rows, const Json& heading, const CompareOptions& options,
                  const std::string& jsonPath) {
  if (!options.csv.empty()) {
    OutputFile output(options.csv);
    output.stream() << csvLine(compareColumns());
    for (const Json& row : rows) output.stream() << csvLine(compareFields(row));
    output.commit();
    std::cout << "wrote " << options.csv << "\n";
  }
  Json all = heading;
  all["rows"] = rows;
  writeTextFile(jsonPath, all.dump(2) + "\n");
  if (!options.json.empty()) std::cout << "wrote " << options.json << "\n";
  if (options.html.empty()) return;
  runPlotScript("compare", {"--out", options.html, "--", jsonPath});
  std::cout << "wrote " << options.html << "\n";
}

// A folder under /tmp for what compare writes only for itself, removed with the object.
struct TemporaryFolder {
  std::string path;
  TemporaryFolder() {
    char folder[] = "/tmp/rtusim_compare_XXXXXX";
    if (::mkdtemp(folder) == nullptr) throw std::runtime_error("cannot make a folder in /tmp");
    path = folder;
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

void runCompare(const ConfigRequest& request, const CompareOptions& options) {
  const std::vector<ArchitectureChoice> choices = parseArchitectures(options.architectures);
  Configuration base = request.resolveUnchecked();
  checkOutputPaths({{"--csv", options.csv}, {"--json", options.json}, {"--html", options.html}},
                   inputPaths(base.values()));
  if (!options.images.empty()) createOutputFolder({"--images", options.images});
  const TemporaryFolder scratch;
  SharedFrame shared;
  if (!options.sceneFile.empty()) flattenSceneFile(options.sceneFile, scratch.path, base, shared);
  const bool mesh = !base.values().scene.meshFile.empty();
  TriangleScene triangles;
  if (mesh) triangles = loadSceneTriangles(base.values());  // the same at every depth
  const int depth = chooseDepth(base, shared, triangles.mesh, choices);
  shared.sets.push_back({"scene.depth", std::to_string(depth)});
  base.set("scene.depth", std::to_string(depth), base.source("scene.depth"));
  base.values().camera = frameCamera(base.values(), shared, triangles.mesh, depth);
  base.values().camera.validate();
  if (!mesh) triangles = loadSceneTriangles(base.values());
  // Difference images for the report go to the scratch folder unless --images keeps them.
  const std::string images = !options.images.empty() ? options.images
                             : options.html.empty()  ? ""
                                                     : scratch.path;
  std::vector<CompareTarget> targets;
  std::vector<Configuration> configurations;
  for (const ArchitectureChoice& choice : choices) {
    targets.push_back(makeTarget(request, choice, shared, base.values().camera, images));
    validateRow(targets.back().configuration);
    configurations.push_back(targets.back().configuration);
  }
  checkSettingsHaveEffect(configurations, request.uses, request.command);
  // Checked: now the long work. A scene file's SVO row reads its frame's image from the cache.
  for (CompareTarget& target : targets)
    if (target.name == SvoKind::kName && !options.sceneFile.empty()) {
      Configuration& configuration = target.configuration;
      const std::string svo =
          cachedFrameSvo(configuration.values().scene.meshFile, depth, options.cacheDir);
      configuration.set("mesh", "", ConfigSource::Preset);
      configuration.set("svo", svo, ConfigSource::Preset);
    }
  traceReference(base.values(), triangles, shared);
  for (CompareTarget& target : targets)
    if (target.name == kRaypipe && mesh) moveRaypipeCamera(target, shared.placement);
  const Camera& camera = base.values().camera;
  const Json heading = {{"scene", shared.triangles},
                        {"width", camera.width},
                        {"height", camera.height},
                        {"depth", base.values().scene.depth}};
  std::cout << "compare: " << shared.triangles << ", " << camera.width << "x" << camera.height
            << ", SVO depth " << base.values().scene.depth << ", " << targets.size()
            << " architectures with " << options.workers << " workers\n";
  std::vector<Json> rows(targets.size());
  std::vector<size_t> indices(targets.size());
  for (size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  Progress progress("compare", targets.size(), "architectures");
  size_t finished = 0, failed = 0;
  runInWorkers(
      indices, options.workers,
      [&](size_t i) {
        return compareRow(targets[i], {*shared.tracer, shared.reference}).dump();
      },
      [&](size_t i, const WorkerOutcome& outcome) {
        rows[i] = outcome.answered ? Json::parse(outcome.line)
                                   : Json{{"architecture", targets[i].name},
                                          {"status", "lost"},
                                          {"error", outcome.failure}};
        failed += rows[i]["status"] != "ok";
        progress.update(++finished, failed);
      });
  progress.finish();
  printTable(rows, std::cout);
  writeOutputs(rows, heading, options,
               options.json.empty() ? scratch.path + "/compare.json" : options.json);
  for (const Json& row : rows)
    if (row["status"] != "ok")
      throw std::runtime_error(row["architecture"].get<std::string>() +
                               " failed: " + row["error"].get<std::string>());
}

}  // namespace

void addCompareCommand(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* command = app.add_subcommand(
      "compare", "one scene and camera on every architecture (the SVO RTU, the triangle RTU with "
                 "BVH, BIH and k-d cores, seed 001's ray pipe): frame rate, memory traffic, "
                 "work per ray and image agreement with the float64 reference, side by side");
  // compare sets the core and the architecture per row itself.
  auto request = addConfigOptions(
      *command, kUseModel | kUseArithmetic | kUseScene | kUseCamera | kUseAccel | kUseWorkload,
      {"--core", "--architecture", "--accel", "--accel-file"});
  command
      ->add_option("--architectures", options->architectures,
                   "NAME or NAME=PRESET list: " + knownArchitectures() +
                       " (the RTU's kinds start from --preset, default cached; the ray pipe "
                       "from the seed's final build)")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--scene-file", options->sceneFile,
                      "an animated scene file (TOML): its first frame flattened into one mesh, "
                      "its camera and frame size");
  command->add_option("--cache-dir", options->cacheDir,
                      "where a scene file's SVO is kept (default: ~/.cache/rtusim/models)");
  command->add_option("--csv", options->csv, "one row per architecture");
  command->add_option("--json", options->json, "the rows in full, each with its fps row");
  command->add_option("--html", options->html,
                      "a self-contained report: the table, plots and difference images");
  command->add_option("--images", options->images,
                      "folder for the difference images (NAME.png per architecture)");
  addWorkersOption(*command, options->workers, "architectures run in parallel (default: all cores)",
                   64);
  command->callback([options, request] { runCompare(*request, *options); });
}

}  // namespace rtu
