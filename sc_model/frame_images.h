#pragma once
// Images of a rendered frame, written through OpenImageIO (format from the file extension:
// PNG, EXR, TIFF, ...).

#include <string>
#include <vector>

#include "camera.h"
#include "fixed_point.h"
#include "traversal_job.h"

namespace rtu {

// Results indexed by job id (= pixel x + y * width); missing pixels are misses.
struct RenderedFrame {
  Camera camera;
  FixedFormat format;
  std::vector<TraversalResult> pixels;

  static RenderedFrame fromResults(const Camera& camera, const FixedFormat& format,
                           const std::vector<TraversalResult>& results);
};

// Lambert-shaded hits over a dark background; the face normal is turned toward the viewer.
void writeShadedImage(const RenderedFrame& frame, const std::string& path);
// t_hit per pixel: float t with misses 0 for EXR/TIFF/HDR files, otherwise grey levels from
// near (white) to far (dark) over the frame's hit range, misses black.
void writeDepthImage(const RenderedFrame& frame, const std::string& path);
// Thesis figure 8.2 and the driver's save_output: misses red, the more cycles the deeper
// (0.95^((cost - 2) / 2) in green and blue), hits grey by normal axis (x 0.7, y 0.9, z 0.5).
void writeCostImage(const RenderedFrame& frame, const std::string& path);

}  // namespace rtu
