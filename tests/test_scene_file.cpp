// Scene files (src/scene/scene_file.h) and the model cache (src/scene/model_cache.h).
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scene/model_cache.h"
#include "scene/scene_file.h"

namespace rtu {
namespace {

const std::string kModels = "[models.ball]\nprocedural = \"sphere\"\ndepth = 4\n";
const std::string kCamera =
    "[camera]\nkeys = [{ time = 0, position = [0, 0, -4], look_at = [0, 0, 0] }]\n";
const std::string kInstance = "[[instances]]\nmodel = \"ball\"\n";

std::string writeScene(const std::string& text) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("rtusim_scene_" + std::to_string(std::rand()) + ".toml"))
                               .string();
  std::ofstream(path) << text;
  return path;
}

// The message of the error reading `text`, which must name the file.
std::string errorOf(const std::string& text) {
  const std::string path = writeScene(text);
  try {
    readSceneFile(path);
  } catch (const SceneFileError& error) {
    std::filesystem::remove(path);
    const std::string message = error.what();
    CHECK_THAT(message, Catch::Contains(path));
    return message;
  }
  std::filesystem::remove(path);
  FAIL("no error for:\n" << text);
  return {};
}

}  // namespace

TEST_CASE("A scene file reads back its models, instances, keys and camera") {
  const std::string path = writeScene(
      "width = 64\nheight = 32\nframes = 3\nframe_rate = 12\n" + kModels + kCamera +
      "[[instances]]\nmodel = \"ball\"\ncolour = [1, 0, 0]\nkeys = [\n"
      "  { time = 0, translation = [0, 0, 0], rotation_deg = [0, 0, 0], scale = [1, 2, 3] },\n"
      "  { time = 2, translation = [4, 0, 0], rotation = [0, 0, 1, 0] },\n]\n");
  const SceneDescription scene = readSceneFile(path, SceneOverrides{5, 0, 0});
  std::filesystem::remove(path);
  CHECK(scene.frames == 5);  // the override wins
  CHECK(scene.width == 64);
  CHECK(scene.frameRate == 12.0);
  REQUIRE(scene.instances.size() == 1);
  const ModelPlacement half = scene.instances[0].placement.at(1.0);
  CHECK(half.translation.x == Approx(2.0));
  CHECK(half.scale == glm::dvec3(1, 2, 3));  // one key: held
  // Halfway from no rotation to 180 degrees about y: 90 degrees, +x goes to -z.
  const glm::dvec3 x = half.rotation * glm::dvec3(1, 0, 0);
  CHECK(x.z == Approx(-1.0));
  CHECK(scene.camera.at(0.0, 64, 32).position.z == -4.0);
}

TEST_CASE("Scene file errors name the file, the line and the key") {
  CHECK_THAT(
      errorOf(kModels + kCamera + kInstance + "keys = [{ time = 0, rotaton = [1, 0, 0, 0] }]\n"),
      Catch::Contains("instances[0].keys[0].rotaton") && Catch::Contains("unknown key"));
  CHECK_THAT(errorOf(kModels + kCamera + "[[instances]]\nmodel = \"bal\"\n"),
             Catch::Contains("'instances[0].model'") && Catch::Contains("no model named 'bal'"));
  CHECK_THAT(errorOf(kModels + kCamera + kInstance +
                     "keys = [{ time = 1, translation = [0, 0, 0] }, "
                     "{ time = 1, translation = [1, 0, 0] }]\n"),
             Catch::Contains("instances[0].keys[1].time") && Catch::Contains("increase"));
  CHECK_THAT(errorOf(kModels + kCamera + kInstance + "keys = [{ time = 0, scale = [1, 0, 1] }]\n"),
             Catch::Contains("instances[0].keys[0].scale"));
  CHECK_THAT(
      errorOf(kModels + kCamera + kInstance + "keys = [{ time = 0, rotation = [0, 0, 0, 0] }]\n"),
      Catch::Contains("instances[0].keys[0].rotation"));
  CHECK_THAT(errorOf("width = 0\n" + kModels + kCamera + kInstance), Catch::Contains("'width'"));
  CHECK_THAT(errorOf("[models.ball]\nprocedural = \"spiral\"\n" + kCamera + kInstance),
             Catch::Contains("models.ball.procedural"));
  CHECK_THAT(errorOf("[models.ball]\nmesh = \"missing.obj\"\n" + kCamera + kInstance),
             Catch::Contains("models.ball.mesh") && Catch::Contains("cannot open"));
  CHECK_THAT(
      errorOf("[models.ball]\nprocedural = \"sphere\"\nsvo = \"x.svo\"\n" + kCamera + kInstance),
      Catch::Contains("models.ball") && Catch::Contains("exactly one"));
  CHECK_THAT(errorOf(kModels + kInstance), Catch::Contains("'camera'"));
  // A camera looking along its up vector makes no image.
  CHECK_THAT(
      errorOf(kModels + kInstance +
              "[camera]\nkeys = [{ time = 0, position = [0, -4, 0], look_at = [0, 0, 0] }]\n"),
      Catch::Contains("camera.keys") && Catch::Contains("frame 0"));
  CHECK_THAT(errorOf(kModels + "[[instances]\n"), Catch::Contains("line 4"));
}

TEST_CASE("Models are built once and then read from the cache by their content") {
  const std::string cache =
      (std::filesystem::temp_directory_path() / ("rtusim_cache_" + std::to_string(std::rand())))
          .string();
  ModelDescription model{"ball", SceneSpec{}};
  model.source.procedural = "shell";
  model.source.depth = 5;
  const SceneModel built = loadSceneModel(model, cache);
  const SceneModel cached = loadSceneModel(model, cache);
  CHECK_FALSE(built.fromCache);
  CHECK(cached.fromCache);
  CHECK(cached.scene.image.words == built.scene.image.words);
  CHECK(std::filesystem::exists(cache + "/" + modelCacheKey(model) + ".svo"));
  // The shell's outer radius is 0.8: its box reaches 0.8 on every axis, within a voxel (1/16).
  CHECK(built.bounds.upper.x == Approx(0.8).margin(1.0 / 16));
  CHECK(built.bounds.lower.y == Approx(-0.8).margin(1.0 / 16));
  ModelDescription deeper = model;
  deeper.source.depth = 6;
  CHECK(modelCacheKey(deeper) != modelCacheKey(model));
  std::filesystem::remove_all(cache);
}

}  // namespace rtu
