#pragma once
// The animated scene description (docs/scenes.md): models, instances of them with keyframed
// placements, a camera path, the frame size, count and rate, read from a TOML file.
//
// Every error is a SceneFileError naming the file, the line where toml++ knows it, and the key
// (`instances[1].keys[0].rotation`); unknown keys are errors, so a misspelt key never goes
// unnoticed. Paths of model files are relative to the scene file's directory.

#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "inputs/camera.h"
#include "inputs/keyframes.h"
#include "kinds/svo/scene_loader.h"

namespace rtu {

class SceneFileError : public std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ModelDescription {
  std::string name;
  SceneSpec source;  // one of procedural, meshFile, svoFile, binvoxFile, with depth and seed
};

struct InstanceDescription {
  std::string name;
  size_t model = 0;  // index into SceneDescription::models
  PlacementTracks placement;
  glm::dvec3 colour{0.8, 0.75, 0.65};
};

struct CameraPath {
  Track<glm::dvec3> position;
  Track<glm::dvec3> lookAt;
  glm::dvec3 up{0.0, 1.0, 0.0};
  double verticalFovDegrees = 50.0;

  Camera at(double time, int width, int height) const;
};

struct SceneDescription {
  std::string path;
  std::vector<ModelDescription> models;
  std::vector<InstanceDescription> instances;
  CameraPath camera;
  int width = 320;
  int height = 180;
  int frames = 48;
  double frameRate = 24.0;

  double timeOf(int frame) const { return frame / frameRate; }
};

// What the command line may set over the file; 0 keeps the file's value.
struct SceneOverrides {
  int frames = 0;
  int width = 0;
  int height = 0;
};

// Throws SceneFileError for an unreadable or malformed file or an impossible setting, such as a
// camera path that makes no image in some frame.
SceneDescription readSceneFile(const std::string& path, const SceneOverrides& overrides = {});

}  // namespace rtu
