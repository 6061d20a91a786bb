#include "app/frame_image_writer.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <glm/common.hpp>

namespace rtu {

FrameImageWriter::FrameImageWriter(const Camera& camera, FrameImagePaths paths)
    : camera_(camera), paths_(std::move(paths)) {
  if (!paths_.image.empty()) {
    shaded_ = std::make_unique<RowImage>(paths_.image, camera.width, camera.height, 3, false);
    shadedRow_.resize(static_cast<size_t>(camera.width) * 3);
  }
  if (!paths_.depthImage.empty()) depth_.assign(camera.pixelCount(), depthSample(FramePixel{}));
  if (!paths_.costImage.empty()) cost_.assign(camera.pixelCount(), CostSample{});
}

size_t FrameImageWriter::bytesPerPixel(const FrameImagePaths& paths) {
  return (paths.image.empty() ? 0 : RowImage::heldBytesPerPixel(paths.image, 3)) +
         (paths.depthImage.empty() ? 0 : sizeof(float)) +
         (paths.costImage.empty() ? 0 : sizeof(CostSample));
}

void FrameImageWriter::place(uint32_t id, const FramePixel& pixel) {
  if (id >= camera_.pixelCount())
    throw std::runtime_error("result for job " + std::to_string(id) + " lies outside the " +
                             std::to_string(camera_.width) + "x" + std::to_string(camera_.height) +
                             " frame");
  if (!depth_.empty()) depth_[id] = depthSample(pixel);
  if (!cost_.empty()) cost_[id] = CostSample{pixel.cost, pixel.hit};
  if (!shaded_) return;
  const int y = static_cast<int>(id / static_cast<uint32_t>(camera_.width));
  const size_t x = id % static_cast<uint32_t>(camera_.width);
  if (y < nextRow_) return;  // a row written already: a pixel placed twice
  const size_t width = static_cast<size_t>(camera_.width);
  while (rows_.size() <= static_cast<size_t>(y - nextRow_))
    rows_.push_back(Row{std::vector<FramePixel>(width), std::vector<bool>(width), 0});
  mostRows_ = std::max(mostRows_, rows_.size());
  Row& row = rows_[static_cast<size_t>(y - nextRow_)];
  row.pixels[x] = pixel;
  if (!row.placed[x]) {
    row.placed[x] = true;
    ++row.count;
  }
  while (!rows_.empty() && rows_.front().count == camera_.width) writeFrontRow();
}

// The oldest row, coloured and written; a row never started is all misses.
void FrameImageWriter::writeFrontRow() {
  const size_t width = static_cast<size_t>(camera_.width);
  const size_t first = static_cast<size_t>(nextRow_) * width;
  for (size_t x = 0; x < width; ++x) {
    const FramePixel pixel = rows_.empty() ? FramePixel{} : rows_.front().pixels[x];
    const glm::vec3 colour = glm::clamp(shadedColour(camera_, first + x, pixel), 0.0f, 1.0f);
    std::copy(&colour.x, &colour.x + 3, &shadedRow_[x * 3]);
  }
  shaded_->write(shadedRow_.data(), 1);
  if (!rows_.empty()) rows_.pop_front();
  ++nextRow_;
}

void FrameImageWriter::finish() {
  if (shaded_) {
    while (nextRow_ < camera_.height) writeFrontRow();
    shaded_->commit();
  }
  if (!paths_.depthImage.empty()) writeDepthImage(camera_, depth_, paths_.depthImage);
  if (!paths_.costImage.empty()) writeCostImage(camera_, cost_, paths_.costImage);
}

}  // namespace rtu
