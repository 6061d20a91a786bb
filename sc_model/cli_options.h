#pragma once
// Command-line options shared by several rtusim commands, bound to CLI11.

#include <CLI/CLI.hpp>

#include "camera.h"
#include "golden_model.h"
#include "model_header.h"
#include "scene_loader.h"

namespace rtu {

void addSceneOptions(CLI::App& command, SceneSpec& scene);
void addCameraOptions(CLI::App& command, Camera& camera, double& epsilon);
void addGoldenOptions(CLI::App& command, GoldenConfig& config);
// --translate, --rotate-deg and --scale of an animated model, each needing `enabledBy`.
void addPlacementOptions(CLI::App& command, ModelPlacement& placement, glm::dvec3& rotationDegrees,
                         CLI::Option* enabledBy);

// Everything that defines one rendered frame: scene, camera and golden model.
struct FrameOptions {
  SceneSpec scene;
  Camera camera;
  double epsilon = kDefaultDirectionEpsilon;
  GoldenConfig config;
};
void addFrameOptions(CLI::App& command, FrameOptions& frame);

}  // namespace rtu
