#include "scene/scene_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include <glm/geometric.hpp>
#include <toml++/toml.h>

#include "base/input_file.h"
#include "base/nesting_depth.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"

namespace rtu {

namespace {

// Reads one scene file; every error names the file, the line and the key.
class SceneFileReader {
 public:
  SceneFileReader(std::string path, SceneOverrides overrides)
      : path_(std::move(path)), overrides_(overrides) {}

  SceneDescription read() {
    toml::table root;
    std::string text;
    try {
      text = readInputFile(path_, "scene file", kMaxSettingsFileBytes);
      checkTomlNesting(text);
    } catch (const std::runtime_error& error) {  // names the file
      throw SceneFileError(error.what());
    } catch (const std::invalid_argument& error) {
      throw SceneFileError("scene file '" + path_ + "': " + error.what());
    }
    try {
      root = toml::parse(text, path_);
    } catch (const toml::parse_error& error) {
      throw SceneFileError("scene file '" + path_ + "', line " +
                           std::to_string(error.source().begin.line) + ": " +
                           std::string(error.description()));
    }
    SceneDescription scene;
    scene.path = path_;
    allowOnly(root, "",
              {"width", "height", "frames", "frame_rate", "models", "instances", "camera"});
    scene.width = integer(root, "", "width", 1, 1 << 14, scene.width);
    scene.height = integer(root, "", "height", 1, 1 << 14, scene.height);
    scene.frames = integer(root, "", "frames", 1, 100000, scene.frames);
    scene.frameRate = real(root, "", "frame_rate", 1e-3, 1000.0, scene.frameRate);
    if (overrides_.frames) scene.frames = overrides_.frames;
    if (overrides_.width) scene.width = overrides_.width;
    if (overrides_.height) scene.height = overrides_.height;
    readModels(root, scene);
    readInstances(root, scene);
    readCamera(root, scene);
    return scene;
  }

 private:
  [[noreturn]] void fail(const toml::node* node, const std::string& key,
                         const std::string& what) const {
    std::string where = "scene file '" + path_ + "'";
    if (node && node->source().begin.line > 0)
      where += ", line " + std::to_string(node->source().begin.line);
    throw SceneFileError(where + ": key '" + key + "': " + what);
  }

  static std::string join(const std::string& prefix, const std::string& key) {
    return prefix.empty() ? key : prefix + "." + key;
  }

  void allowOnly(const toml::table& table, const std::string& prefix,
                 const std::set<std::string>& known) const {
    for (const auto& [key, node] : table) {
      if (known.count(std::string(key.str()))) continue;
      std::string list;
      for (const std::string& name : known) list += (list.empty() ? "" : ", ") + name;
      fail(&node, join(prefix, std::string(key.str())), "unknown key (known here: " + list + ")");
    }
  }

  double real(const toml::table& table, const std::string& prefix, const std::string& key,
              double low, double high, double otherwise) const {
    const toml::node* node = table.get(key);
    if (!node) return otherwise;
    const std::optional<double> value = node->value<double>();
    if (!value || !std::isfinite(*value)) fail(node, join(prefix, key), "expected a number");
    if (*value < low || *value > high)
      fail(node, join(prefix, key),
           "must lie in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
    return *value;
  }

  int integer(const toml::table& table, const std::string& prefix, const std::string& key, int low,
              int high, int otherwise) const {
    const toml::node* node = table.get(key);
    if (!node) return otherwise;
    if (!node->is_integer()) fail(node, join(prefix, key), "expected an integer");
    const int64_t value = node->as_integer()->get();
    if (value < low || value > high)
      fail(node, join(prefix, key),
           std::to_string(value) + " is outside [" + std::to_string(low) + ", " +
               std::to_string(high) + "]");
    return static_cast<int>(value);
  }

  std::string text(const toml::table& table, const std::string& prefix,
                   const std::string& key) const {
    const toml::node* node = table.get(key);
    if (!node || !node->is_string())
      fail(node ? node : &table, join(prefix, key), "expected a string");
    return node->as_string()->get();
  }

  // n finite numbers, each within [-limit, limit].
  std::vector<double> numbers(const toml::node& node, const std::string& key, size_t count,
                              double limit, const std::string& meaning) const {
    const toml::array* array = node.as_array();
    const std::string expected = "expected " + std::to_string(count) + " numbers (" + meaning + ")";
    if (!array || array->size() != count) fail(&node, key, expected);
    std::vector<double> values;
    for (const toml::node& element : *array) {
      const std::optional<double> value = element.value<double>();
      if (!value || !std::isfinite(*value)) fail(&node, key, expected);
      if (std::abs(*value) > limit)
        fail(&node, key,
             "component " + std::to_string(*value) + " beyond " + std::to_string(limit));
      values.push_back(*value);
    }
    return values;
  }

  glm::dvec3 vector3(const toml::node& node, const std::string& key, double limit = 1e9) const {
    const std::vector<double> v = numbers(node, key, 3, limit, "x, y, z");
    return glm::dvec3(v[0], v[1], v[2]);
  }

  const toml::table& tableAt(const toml::node& node, const std::string& key) const {
    if (!node.is_table()) fail(&node, key, "expected a table");
    return *node.as_table();
  }

  // Relative to the scene file's directory; must be a regular file.
  std::string inputFile(const toml::table& table, const std::string& prefix,
                        const std::string& key) const {
    std::filesystem::path file = text(table, prefix, key);
    if (file.is_relative()) file = std::filesystem::path(path_).parent_path() / file;
    try {
      inputFileBytes(file.string(), "");
    } catch (const std::runtime_error& error) {
      fail(table.get(key), join(prefix, key), error.what());
    }
    return file.string();
  }

  ModelDescription readModel(const std::string& name, const toml::table& table,
                             const std::string& prefix) const {
    allowOnly(table, prefix, {"procedural", "mesh", "svo", "binvox", "depth", "seed", "root"});
    ModelDescription model{name, SceneSpec{}};
    SceneSpec& source = model.source;
    int sources = 0;
    for (const char* key : {"procedural", "mesh", "svo", "binvox"}) sources += table.contains(key);
    if (sources != 1) fail(&table, prefix, "give exactly one of procedural, mesh, svo and binvox");
    if (table.contains("procedural")) {
      source.procedural = text(table, prefix, "procedural");
      const auto& known = proceduralSceneNames();
      if (std::find(known.begin(), known.end(), source.procedural) == known.end())
        fail(table.get("procedural"), join(prefix, "procedural"),
             "unknown procedural scene '" + source.procedural + "'");
    }
    if (table.contains("mesh")) source.meshFile = inputFile(table, prefix, "mesh");
    if (table.contains("svo")) source.svoFile = inputFile(table, prefix, "svo");
    if (table.contains("binvox")) source.binvoxFile = inputFile(table, prefix, "binvox");
    source.depth = integer(table, prefix, "depth", source.meshFile.empty() ? 1 : 2, kMaxSvoDepth,
                           source.depth);
    source.seed = static_cast<uint64_t>(integer(table, prefix, "seed", 0, 1 << 30, 1));
    source.root = static_cast<uint32_t>(integer(table, prefix, "root", 0, 1 << 30, 0));
    return model;
  }

  void readModels(const toml::table& root, SceneDescription& scene) const {
    const toml::node* node = root.get("models");
    if (!node) fail(&root, "models", "missing: a scene needs at least one model");
    for (const auto& [key, value] : tableAt(*node, "models")) {
      const std::string prefix = "models." + std::string(key.str());
      scene.models.push_back(readModel(std::string(key.str()), tableAt(value, prefix), prefix));
    }
    if (scene.models.empty()) fail(node, "models", "a scene needs at least one model");
  }

  size_t modelIndex(const SceneDescription& scene, const toml::table& table,
                    const std::string& prefix) const {
    const std::string name = text(table, prefix, "model");
    for (size_t i = 0; i < scene.models.size(); ++i)
      if (scene.models[i].name == name) return i;
    fail(table.get("model"), join(prefix, "model"), "no model named '" + name + "'");
  }

  glm::dvec3 scale(const toml::node& node, const std::string& key) const {
    glm::dvec3 value;
    if (node.value<double>())
      value = glm::dvec3(*node.value<double>());
    else
      value = vector3(node, key, 1e30);
    for (int axis = 0; axis < 3; ++axis)
      if (!(value[axis] >= kMinInverseScale && value[axis] <= kMaxInverseScale))
        fail(&node, key, "a scale must lie in [2^-32, 2^32] on every axis");
    return value;
  }

  glm::dquat rotation(const toml::table& key, const std::string& prefix) const {
    if (key.contains("rotation") && key.contains("rotation_deg"))
      fail(&key, prefix, "give rotation or rotation_deg, not both");
    if (const toml::node* node = key.get("rotation_deg"))
      return quaternionFromEulerDegrees(vector3(*node, join(prefix, "rotation_deg"), 1e6));
    const toml::node* node = key.get("rotation");
    const std::vector<double> q = numbers(*node, join(prefix, "rotation"), 4, 1e6, "w, x, y, z");
    const glm::dquat quaternion(q[0], q[1], q[2], q[3]);
    if (glm::length(quaternion) < 1e-9)
      fail(node, join(prefix, "rotation"), "a zero quaternion is no rotation");
    return glm::normalize(quaternion);
  }

  void addKey(PlacementTracks& tracks, const toml::table& key, const std::string& prefix) const {
    allowOnly(key, prefix, {"time", "translation", "rotation", "rotation_deg", "scale"});
    const double time = real(key, prefix, "time", 0.0, 1e6, 0.0);
    try {
      if (const toml::node* node = key.get("translation"))
        tracks.translation.add(time,
                               vector3(*node, join(prefix, "translation"), kMaxModelCoordinate));
      if (key.contains("rotation") || key.contains("rotation_deg"))
        tracks.rotation.add(time, rotation(key, prefix));
      if (const toml::node* node = key.get("scale"))
        tracks.scale.add(time, scale(*node, join(prefix, "scale")));
    } catch (const std::invalid_argument& error) {
      fail(key.get("time"), join(prefix, "time"),
           std::string(error.what()) + " within each channel");
    }
  }

  InstanceDescription readInstance(const SceneDescription& scene, const toml::table& table,
                                   const std::string& prefix) const {
    allowOnly(table, prefix, {"name", "model", "colour", "keys"});
    InstanceDescription instance;
    instance.model = modelIndex(scene, table, prefix);
    instance.name = table.contains("name") ? text(table, prefix, "name")
                                           : scene.models[instance.model].name;
    if (const toml::node* node = table.get("colour")) {
      instance.colour = vector3(*node, join(prefix, "colour"), 1.0);
      if (glm::any(glm::lessThan(instance.colour, glm::dvec3(0.0))))
        fail(node, join(prefix, "colour"), "components lie in [0, 1]");
    }
    if (const toml::node* keys = table.get("keys")) {
      const toml::array* array = keys->as_array();
      if (!array) fail(keys, join(prefix, "keys"), "expected an array of tables ([[...keys]])");
      for (size_t i = 0; i < array->size(); ++i) {
        const std::string keyPrefix = prefix + ".keys[" + std::to_string(i) + "]";
        addKey(instance.placement, tableAt(*array->get(i), keyPrefix), keyPrefix);
      }
    }
    return instance;
  }

  void readInstances(const toml::table& root, SceneDescription& scene) const {
    const toml::node* node = root.get("instances");
    const toml::array* array = node ? node->as_array() : nullptr;
    if (!array || array->empty())
      fail(node ? node : &root, "instances", "a scene needs at least one [[instances]] table");
    for (size_t i = 0; i < array->size(); ++i) {
      const std::string prefix = "instances[" + std::to_string(i) + "]";
      scene.instances.push_back(readInstance(scene, tableAt(*array->get(i), prefix), prefix));
    }
  }

  void addCameraKey(CameraPath& camera, const toml::table& key, const std::string& prefix) const {
    allowOnly(key, prefix, {"time", "position", "look_at"});
    const double time = real(key, prefix, "time", 0.0, 1e6, 0.0);
    try {
      if (const toml::node* node = key.get("position"))
        camera.position.add(time, vector3(*node, join(prefix, "position")));
      if (const toml::node* node = key.get("look_at"))
        camera.lookAt.add(time, vector3(*node, join(prefix, "look_at")));
    } catch (const std::invalid_argument& error) {
      fail(key.get("time"), join(prefix, "time"),
           std::string(error.what()) + " within each channel");
    }
  }

  void readCamera(const toml::table& root, SceneDescription& scene) const {
    const toml::node* node = root.get("camera");
    if (!node) fail(&root, "camera", "missing: a scene needs a camera with at least one key");
    const toml::table& table = tableAt(*node, "camera");
    allowOnly(table, "camera", {"fov", "up", "keys"});
    CameraPath& camera = scene.camera;
    camera.verticalFovDegrees = real(table, "camera", "fov", 1.0, 170.0, camera.verticalFovDegrees);
    if (const toml::node* up = table.get("up")) camera.up = vector3(*up, "camera.up");
    const toml::node* keys = table.get("keys");
    const toml::array* array = keys ? keys->as_array() : nullptr;
    if (!array || array->empty())
      fail(keys ? keys : node, "camera.keys", "expected at least one [[camera.keys]]");
    for (size_t i = 0; i < array->size(); ++i) {
      const std::string prefix = "camera.keys[" + std::to_string(i) + "]";
      addCameraKey(camera, tableAt(*array->get(i), prefix), prefix);
    }
    if (camera.position.empty()) fail(keys, "camera.keys", "no key gives a position");
    if (camera.lookAt.empty()) fail(keys, "camera.keys", "no key gives look_at");
    checkCameraFrames(scene, keys);
  }

  // Every frame's camera must make rays: caught here, before any model is built.
  void checkCameraFrames(const SceneDescription& scene, const toml::node* keys) const {
    for (int frame = 0; frame < scene.frames; ++frame) {
      try {
        scene.camera.at(scene.timeOf(frame), scene.width, scene.height).validate();
      } catch (const std::invalid_argument& error) {
        fail(keys, "camera.keys", "frame " + std::to_string(frame) + ": " + error.what());
      }
    }
  }

  std::string path_;
  SceneOverrides overrides_;
};

}  // namespace

Camera CameraPath::at(double time, int width, int height) const {
  Camera camera;
  camera.position = position.at(time, lerpVector, camera.position);
  camera.lookAt = lookAt.at(time, lerpVector, camera.lookAt);
  camera.up = up;
  camera.verticalFovDegrees = verticalFovDegrees;
  camera.width = width;
  camera.height = height;
  return camera;
}

SceneDescription readSceneFile(const std::string& path, const SceneOverrides& overrides) {
  return SceneFileReader(path, overrides).read();
}

}  // namespace rtu
