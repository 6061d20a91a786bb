#include "inputs/light.h"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "inputs/camera.h"

namespace rtu {

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

// The parts of "shape:a:b:c" after the shape.
std::vector<std::string> partsAfter(const std::string& text, size_t colon) {
  std::vector<std::string> parts;
  while (colon != std::string::npos) {
    const size_t next = text.find(':', colon + 1);
    parts.push_back(text.substr(colon + 1, next == std::string::npos ? next : next - colon - 1));
    colon = next;
  }
  return parts;
}

[[noreturn]] void refuse(const std::string& option, const std::string& text, const char* why) {
  throw std::invalid_argument(option + " '" + text + "': " + why +
                              " (a light is x,y,z, rect:cx,cy,cz:ux,uy,uz:vx,vy,vz or "
                              "disc:cx,cy,cz:nx,ny,nz:r)");
}

}  // namespace

glm::dvec3 Light::sample(RaySampler& sampler) const {
  switch (shape) {
    case Shape::Point: return position;
    case Shape::Rectangle: {
      const double a = sampler.uniform() - 0.5;
      return position + a * edgeU + (sampler.uniform() - 0.5) * edgeV;
    }
    case Shape::Disc: break;
  }
  // Uniform on the disc: radius r sqrt(s), angle 2 pi t, in a basis about the axis.
  const double r = radius * std::sqrt(sampler.uniform());
  const double phi = kTwoPi * sampler.uniform();
  const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 tangent = glm::normalize(glm::cross(normal, helper));
  const glm::dvec3 bitangent = glm::cross(normal, tangent);
  return position + r * (std::cos(phi) * tangent + std::sin(phi) * bitangent);
}

const char* toString(Light::Shape shape) {
  switch (shape) {
    case Light::Shape::Point: return "point";
    case Light::Shape::Rectangle: return "rect";
    case Light::Shape::Disc: break;
  }
  return "disc";
}

Light parseLight(const std::string& text, const std::string& option) {
  Light light;
  const size_t colon = text.find(':');
  if (colon == std::string::npos) {
    light.position = parseVector(text, option);
    return light;
  }
  const std::string shape = text.substr(0, colon);
  const std::vector<std::string> parts = partsAfter(text, colon);
  if (parts.size() != 3) refuse(option, text, "an area light has three parts after its shape");
  light.position = parseVector(parts[0], option);
  if (shape == "rect") {
    light.shape = Light::Shape::Rectangle;
    light.edgeU = parseVector(parts[1], option);
    light.edgeV = parseVector(parts[2], option);
    if (!(glm::length(glm::cross(light.edgeU, light.edgeV)) > 0.0))
      refuse(option, text, "a rectangle's edges must be neither zero nor parallel");
    return light;
  }
  if (shape != "disc") refuse(option, text, "the shape is rect or disc");
  light.shape = Light::Shape::Disc;
  const glm::dvec3 axis = parseVector(parts[1], option);
  if (!(glm::length(axis) > 0.0)) refuse(option, text, "a disc's axis must not be zero");
  light.normal = glm::normalize(axis);
  char* end = nullptr;
  light.radius = std::strtod(parts[2].c_str(), &end);
  if (parts[2].empty() || *end != '\0' || !(light.radius > 0.0) || !std::isfinite(light.radius))
    refuse(option, text, "a disc's radius must be a positive number");
  return light;
}

}  // namespace rtu
