#include "frame_images.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <glm/geometric.hpp>

namespace rtu {

namespace {

using Pixel = glm::vec3;

void writeImage(const std::string& path, int width, int height, int channels,
                const std::vector<float>& data, bool floatFile) {
  auto output = OIIO::ImageOutput::create(path);
  if (!output)
    throw std::runtime_error("cannot write image '" + path + "': " + OIIO::geterror());
  const OIIO::ImageSpec spec(width, height, channels,
                             floatFile ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (!output->open(path, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, data.data()) ||
      !output->close())
    throw std::runtime_error("cannot write image '" + path + "': " + output->geterror());
}

void writeRgb(const RenderedFrame& frame, const std::string& path, Pixel (*shade)(const RenderedFrame&, size_t)) {
  std::vector<float> data(frame.pixels.size() * 3);
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    const Pixel colour = glm::clamp(shade(frame, i), 0.0f, 1.0f);
    std::copy(&colour.x, &colour.x + 3, &data[i * 3]);
  }
  writeImage(path, frame.camera.width, frame.camera.height, 3, data, false);
}

bool isFloatFormat(const std::string& path) {
  const std::string extension = path.substr(path.find_last_of('.') + 1);
  return extension == "exr" || extension == "tif" || extension == "tiff" || extension == "hdr";
}

int normalAxis(const TraversalResult& result) {
  return result.normal[0] ? 0 : result.normal[1] ? 1 : 2;
}

Pixel shadeLambert(const RenderedFrame& frame, size_t index) {
  const TraversalResult& result = frame.pixels[index];
  const int width = frame.camera.width;
  const glm::dvec3 direction =
      frame.camera.primaryRay(static_cast<int>(index % width), static_cast<int>(index / width))
          .direction;
  if (!result.hit) return Pixel(0.08f, 0.09f, 0.12f);
  const int axis = normalAxis(result);
  glm::dvec3 normal(0.0);
  normal[axis] = direction[axis] > 0 ? -1.0 : 1.0;  // the face the ray entered looks back at it
  const glm::dvec3 light = glm::normalize(glm::dvec3(0.45, 0.8, -0.4));
  const float lambert = static_cast<float>(std::max(0.0, glm::dot(normal, light)));
  return Pixel(0.86f, 0.80f, 0.68f) * (0.22f + 0.78f * lambert);
}

Pixel shadeCost(const RenderedFrame& frame, size_t index) {
  const TraversalResult& result = frame.pixels[index];
  if (!result.hit) {
    const float fade = std::pow(0.95f, (static_cast<float>(result.cost) - 2.0f) / 2.0f);
    return Pixel(1.0f, fade, fade);
  }
  static const float greys[3] = {0.7f, 0.9f, 0.5f};
  return Pixel(greys[normalAxis(result)]);
}

}  // namespace

RenderedFrame RenderedFrame::fromResults(const Camera& camera, const FixedFormat& format,
                         const std::vector<TraversalResult>& results) {
  RenderedFrame frame{camera, format, std::vector<TraversalResult>(camera.pixelCount())};
  for (const TraversalResult& result : results) {
    if (result.id() >= frame.pixels.size())
      throw std::runtime_error("result for job " + std::to_string(result.id()) +
                               " lies outside the " + std::to_string(camera.width) + "x" +
                               std::to_string(camera.height) + " frame");
    frame.pixels[result.id()] = result;
  }
  return frame;
}

void writeShadedImage(const RenderedFrame& frame, const std::string& path) {
  writeRgb(frame, path, shadeLambert);
}

void writeCostImage(const RenderedFrame& frame, const std::string& path) {
  writeRgb(frame, path, shadeCost);
}

void writeDepthImage(const RenderedFrame& frame, const std::string& path) {
  std::vector<float> depth(frame.pixels.size(), 0.0f);
  float nearest = std::numeric_limits<float>::max();
  float farthest = std::numeric_limits<float>::lowest();
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    if (!frame.pixels[i].hit) continue;
    depth[i] = static_cast<float>(frame.format.toDouble(frame.pixels[i].tHit));
    nearest = std::min(nearest, depth[i]);
    farthest = std::max(farthest, depth[i]);
  }
  const bool floatFile = isFloatFormat(path);
  if (!floatFile) {
    const float range = std::max(farthest - nearest, 1e-6f);
    for (size_t i = 0; i < depth.size(); ++i)
      depth[i] = frame.pixels[i].hit ? 1.0f - 0.85f * (depth[i] - nearest) / range : 0.0f;
  }
  writeImage(path, frame.camera.width, frame.camera.height, 1, depth, floatFile);
}

}  // namespace rtu
