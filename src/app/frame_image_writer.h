#pragma once
// The images `render` writes of a frame whose pixels are not held (no secondary pass reads them:
// app/frame_stream.h), placed as the results leave the run: the shaded image is coloured and
// written row by row as its rows complete (RowImage: a PNG file's rows are encoded at once), so
// only the rows the results in flight touch are held; the depth and cost images keep a sample
// of 4 and 8 bytes a pixel (their scales are the frame's range) and are written by finish().
// Results arrive nearly in job order, a few hundred out of it at most (the RTU's buffers).

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/frame_images.h"
#include "app/row_image.h"
#include "inputs/camera.h"

namespace rtu {

// The images `render` writes of any architecture's frame: their paths, empty for those not
// asked.
struct FrameImagePaths {
  std::string image, depthImage, costImage;
  bool any() const { return !image.empty() || !depthImage.empty() || !costImage.empty(); }
};

class FrameImageWriter final : public PixelSink {
 public:
  // Throws std::runtime_error naming a file that cannot be created.
  FrameImageWriter(const Camera& camera, FrameImagePaths paths);

  void place(uint32_t id, const FramePixel& pixel) override;
  // Writes what is left (pixels never placed are misses) and renames the files into place.
  void finish();

  // The most rows of the shaded image held at once.
  size_t mostRowsHeld() const { return mostRows_; }
  // Bytes a pixel of the frame the images keep whatever its rows (the depth and cost samples, the
  // shaded image's rows in a format written whole: RowImage::heldBytesPerPixel).
  static size_t bytesPerPixel(const FrameImagePaths& paths);

 private:
  // A row of the shaded image not yet written: its pixels and which were placed.
  struct Row {
    std::vector<FramePixel> pixels;
    std::vector<bool> placed;
    int count = 0;
  };

  void writeFrontRow();

  Camera camera_;
  FrameImagePaths paths_;
  std::unique_ptr<RowImage> shaded_;
  std::deque<Row> rows_;  // from row nextRow_ on
  int nextRow_ = 0;
  size_t mostRows_ = 0;
  std::vector<float> shadedRow_;  // a row's colours
  std::vector<float> depth_;
  std::vector<CostSample> cost_;
};

}  // namespace rtu
