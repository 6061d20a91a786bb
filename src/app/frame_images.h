#pragma once
// Images of a rendered frame, written through OpenImageIO (format from the file extension:
// PNG, EXR, TIFF, ...). OpenImageIO is called in librtusim_images.so (image_plugin.cpp), loaded
// on first use (src/base/plugin_loader.h): a missing module is a std::runtime_error naming it.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "inputs/camera.h"
#include "kinds/svo/fixed_point.h"
#include "kinds/svo/precision.h"
#include "kinds/svo/thesis_records.h"

namespace rtu {

// What the images show of a pixel's ray, whichever kind traced it.
struct FramePixel {
  bool hit = false;
  double t = 0;  // the hit's distance along the ray (0 on a miss)
  uint32_t cost = 0;
  glm::dvec3 normal{0.0};  // the surface's at the hit, either way round, any length but 0
  int64_t triangle = -1;  // the hit triangle's index in the scene's mesh (triangle kinds, ray pipe)
  // Secondary passes (explore/ray_passes.h): the share of the hit's shadow rays that reached the
  // light, and of its ambient-occlusion rays that met nothing; 1 without such a pass.
  float lightOpen = 1.0f;
  float ambientOpen = 1.0f;
};

// Where a frame's pixels go as its results are taken: held whole (RenderedFrame) or into the
// images as their rows complete (FrameImageWriter, app/frame_image_writer.h).
class PixelSink {
 public:
  virtual ~PixelSink() = default;
  // The pixel of job id `id` (= pixel x + y * width). Throws std::runtime_error for an id outside
  // the frame.
  virtual void place(uint32_t id, const FramePixel& pixel) = 0;
};

// Pixels indexed by job id (= pixel x + y * width); missing pixels are misses.
struct RenderedFrame : PixelSink {
  Camera camera;
  std::vector<FramePixel> pixels;

  explicit RenderedFrame(const Camera& camera);  // every pixel a miss
  void place(uint32_t id, const FramePixel& pixel) override;
  // The SVO kind's results: t from `format`, the normal of the voxel face entered.
  static RenderedFrame fromResults(const Camera& camera, const FixedFormat& format,
                                   const std::vector<TraversalResult>& results);
};

// The pixel of an SVO result: t from `format`, the normal of the voxel face entered.
FramePixel svoPixel(const FixedFormat& format, const TraversalResult& result);

// Throws std::invalid_argument naming `option` when no image format writes `path`'s extension;
// for checking outputs before a run.
void checkImageFormat(const std::string& option, const std::string& path);

// An image file in the format its extension names, from `channels` floats a pixel (in [0, 1]
// for 8-bit files; 32-bit float samples when `floatFile`), rows from the top. Written whole:
// `data` holds every row (RowImage, app/row_image.h, writes rows as they come).
void writeImageFile(const std::string& path, int width, int height, int channels,
                    const std::vector<float>& data, bool floatFile);

// Any RGB picture: `rgb` holds width x height pixels of three floats in [0, 1], rows from the top.
void writeRgbImage(const std::string& path, int width, int height, const std::vector<float>& rgb);

// A shaded pixel's colour, for the pixel of job `index` (writeShadedImage).
glm::vec3 shadedColour(const Camera& camera, size_t index, const FramePixel& pixel);

// What the depth and cost images read of a pixel: 4 and 8 bytes, kept for a frame whose pixels
// are not (FrameImageWriter), as both images' scales are the frame's range.
struct CostSample {
  uint32_t cost = 0;
  bool hit = false;
};
// A pixel's depth sample: its t, NaN for a miss.
float depthSample(const FramePixel& pixel);

// Lambert-shaded hits over a dark background; the face normal is turned toward the viewer. The
// light term is scaled by the pixel's lightOpen (shadows), the ambient term by ambientOpen (AO).
void writeShadedImage(const RenderedFrame& frame, const std::string& path);
// t_hit per pixel: float t with misses 0 for EXR/TIFF/HDR files, otherwise grey levels from
// near (white) to far (dark) over the frame's hit range, misses black.
void writeDepthImage(const RenderedFrame& frame, const std::string& path);
void writeDepthImage(const Camera& camera, const std::vector<float>& samples,
                     const std::string& path);
// Whether `path`'s format takes float samples (EXR, TIFF, HDR): the depth image's t.
bool isFloatFormat(const std::string& path);
// Cost heat map after thesis figure 8.2: every pixel coloured by its cost in cycles on one
// logarithmic scale from the frame's cheapest to its dearest ray; hits in viridis (dark blue
// cheap, yellow dear), misses in red (pale pink cheap, dark red dear). Frames at least 96 pixels
// wide get a 46-pixel strip below: both colour ramps, ticks and labels in cycles (the minimum,
// round values, the maximum), and from 200 pixels a hit/miss/cycles legend. Labels use
// DejaVu Sans through OpenImageIO, or a built-in 5x7 bitmap font when no font loads.
void writeCostImage(const RenderedFrame& frame, const std::string& path);
void writeCostImage(const Camera& camera, const std::vector<CostSample>& samples,
                    const std::string& path);
// One format against float64 per pixel (verdicts in pixel order): both miss near black, agreeing
// hits grey, false hits blue, missed hits red, hits on a different first voxel yellow.
void writePrecisionImage(const Camera& camera, const std::vector<PrecisionVerdict>& verdicts,
                         const std::string& path);

}  // namespace rtu
