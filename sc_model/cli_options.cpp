#include "cli_options.h"

namespace rtu {

void addSceneOptions(CLI::App& command, SceneSpec& scene) {
  command.add_option("--scene", scene.procedural,
                     "procedural scene: sphere, shell, menger, terrain or noise")
      ->capture_default_str();
  command.add_option("--svo", scene.svoFile, "SVO memory image (.svo, little-endian u32 words)")
      ->check(CLI::ExistingFile);
  command.add_option("--mesh", scene.meshFile, "triangle mesh to voxelize (OBJ or PLY)")
      ->check(CLI::ExistingFile);
  command.add_option("--binvox", scene.binvoxFile, "voxel file to import (.binvox)")
      ->check(CLI::ExistingFile);
  command.add_option("--depth", scene.depth, "octree depth for procedural scenes and meshes")
      ->capture_default_str()
      ->check(CLI::Range(1, 16));
  command.add_option("--seed", scene.seed, "seed of the random scenes (terrain, noise)")
      ->capture_default_str();
  command.add_option("--root", scene.root, "word address of the root descriptor")
      ->capture_default_str();
}

void addCameraOptions(CLI::App& command, Camera& camera, double& epsilon) {
  command.add_option("--width", camera.width, "image width in pixels")->capture_default_str();
  command.add_option("--height", camera.height, "image height in pixels")->capture_default_str();
  command.add_option("--fov", camera.verticalFovDegrees, "vertical field of view in degrees")
      ->capture_default_str();
  command.add_option_function<std::string>(
      "--camera", [&camera](const std::string& text) { camera.position = parseVector(text, "--camera"); },
      "camera position x,y,z (default -1.9,1.3,-2.6)");
  command.add_option_function<std::string>(
      "--look-at", [&camera](const std::string& text) { camera.lookAt = parseVector(text, "--look-at"); },
      "point the camera looks at x,y,z (default 0,0,0)");
  command.add_option_function<std::string>(
      "--up", [&camera](const std::string& text) { camera.up = parseVector(text, "--up"); },
      "camera up vector x,y,z (default 0,1,0)");
  command.add_option("--epsilon", epsilon,
                     "replaces exact zero direction components (thesis driver: 0.0001)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

void addGoldenOptions(CLI::App& command, GoldenConfig& config) {
  command.add_option("--total-bits", config.format.totalBits, "fixed-point width in bits")
      ->capture_default_str();
  command.add_option("--fraction-bits", config.format.fractionBits,
                     "fixed-point fraction bits")
      ->capture_default_str();
  command.add_option_function<std::string>(
      "--conversion",
      [&config](const std::string& name) { config.conversion = parseFloatConversion(name); },
      "float-to-fixed conversion: rtl (as the hardware computes it, default) or exact")
      ->check(CLI::IsMember({"rtl", "exact"}));
  command.add_option("--stack-frames", config.stackFrames,
                     "traversal stack depth in frames (RTL: 11)")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxStackFrames));
}

void addPlacementOptions(CLI::App& command, ModelPlacement& placement, glm::dvec3& rotationDegrees,
                         CLI::Option* enabledBy) {
  command
      .add_option_function<std::string>(
          "--translate",
          [&placement](const std::string& text) {
            placement.translation = parseVector(text, "--translate");
          },
          "model translation x,y,z in world units (default 0,0,0)")
      ->needs(enabledBy);
  command
      .add_option_function<std::string>(
          "--rotate-deg",
          [&rotationDegrees](const std::string& text) {
            rotationDegrees = parseVector(text, "--rotate-deg");
          },
          "model rotation about the world x, then y, then z axis, in degrees (default 0,0,0)")
      ->needs(enabledBy);
  command
      .add_option_function<std::string>(
          "--scale",
          [&placement](const std::string& text) { placement.scale = parseVector(text, "--scale"); },
          "model scale along its x,y,z axes, each within [2^-32, 2^32] (default 1,1,1)")
      ->needs(enabledBy);
}

void addFrameOptions(CLI::App& command, FrameOptions& frame) {
  addSceneOptions(command, frame.scene);
  addCameraOptions(command, frame.camera, frame.epsilon);
  addGoldenOptions(command, frame.config);
}

}  // namespace rtu
