#include "app/placement_flags.h"

#include "inputs/camera.h"

namespace rtu {

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

const CLI::Validator kNotNegative(
    [](std::string& text) {
      const size_t first = text.find_first_not_of(" \t");
      if (first == std::string::npos || text[first] != '-') return std::string();
      return "must not be negative, got " + text;
    },
    "NOT NEGATIVE");

}  // namespace rtu
