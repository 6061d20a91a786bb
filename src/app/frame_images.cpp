#include "app/frame_images.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "app/row_image.h"
#include "base/output_file.h"
#include "base/plugin_loader.h"

namespace rtu {

namespace {

using Pixel = glm::vec3;

// ---- librtusim_images.so (image_plugin.cpp): OpenImageIO, loaded on first use. -------------

constexpr const char* kImagesModule = "librtusim_images.so";
constexpr const char* kImagesPurpose = "needed to write images";

}  // namespace

void writeImageFile(const std::string& path, int width, int height, int channels,
                    const std::vector<float>& data, bool floatFile) {
  using WriteFunction = const char*(const char*, const char*, int, int, int, const float*, int,
                                    const unsigned char**, size_t*);
  static WriteFunction* const write =
      pluginFunction<WriteFunction>(kImagesModule, "rtusim_images_write", kImagesPurpose);
  OutputFile file(path);
  const unsigned char* bytes = nullptr;
  size_t size = 0;
  if (const char* error = write(path.c_str(), file.writePath().c_str(), width, height, channels,
                                data.data(), floatFile, &bytes, &size))
    file.fail(error);
  if (bytes)
    file.stream().write(reinterpret_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  file.commit();
}

void checkImageFormat(const std::string& option, const std::string& path) {
  using CheckFunction = const char*(const char*);
  static CheckFunction* const check =
      pluginFunction<CheckFunction>(kImagesModule, "rtusim_images_format_error", kImagesPurpose);
  if (const char* error = check(path.c_str()))
    throw std::invalid_argument(option + " '" + path + "': no image format: " + error);
}

namespace {

// An RGB float image, rows top to bottom.
struct Canvas {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;

  Canvas(int width, int height, Pixel background)
      : width(width), height(height), rgb(static_cast<size_t>(width) * height * 3) {
    fill(0, 0, width, height, background);
  }
  void set(int x, int y, Pixel colour) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    colour = glm::clamp(colour, 0.0f, 1.0f);
    std::copy(&colour.x, &colour.x + 3, &rgb[(static_cast<size_t>(y) * width + x) * 3]);
  }
  void fill(int x, int y, int w, int h, Pixel colour) {
    for (int row = y; row < y + h; ++row)
      for (int column = x; column < x + w; ++column) set(column, row, colour);
  }
};

// ---- Text for the cost scale: OpenImageIO's render_text with DejaVu Sans, or, when no font
// loads, a built-in 5x7 bitmap font holding the characters the scale uses. ----------------------

enum class Align { Left = 0, Right = 1, Centre = 2 };

struct Glyph {
  char character;
  std::array<uint8_t, 7> rows;  // bit 4 is the leftmost column
};

constexpr Glyph kGlyphs[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}},
    {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}},
    {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}},
    {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}},
    {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}},
    {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}},
    {'c', {0x00, 0x00, 0x0E, 0x10, 0x10, 0x11, 0x0E}},
    {'e', {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E}},
    {'h', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'i', {0x04, 0x00, 0x0C, 0x04, 0x04, 0x04, 0x0E}},
    {'l', {0x0C, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'m', {0x00, 0x00, 0x1A, 0x15, 0x15, 0x11, 0x11}},
    {'s', {0x00, 0x00, 0x0E, 0x10, 0x0E, 0x01, 0x1E}},
    {'t', {0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06}},
    {'y', {0x00, 0x00, 0x11, 0x11, 0x0F, 0x01, 0x0E}},
};

class TextPainter {
 public:
  static constexpr int kFontSize = 11;  // pixels, for render_text

  TextPainter() {
    using WidthFunction = int(const char*, int);
    using DrawFunction = int(float*, int, int, int, int, const char*, int, const float*, int);
    width_ =
        pluginFunction<WidthFunction>(kImagesModule, "rtusim_images_text_width", kImagesPurpose);
    draw_ = pluginFunction<DrawFunction>(kImagesModule, "rtusim_images_draw_text", kImagesPurpose);
    useFont_ = width_("0123456789", kFontSize) > 0;
  }

  int width(const std::string& text) const {
    const int fontWidth = useFont_ ? width_(text.c_str(), kFontSize) : -1;
    return fontWidth > 0 ? fontWidth : static_cast<int>(text.size()) * 6 - 1;
  }

  // `baseline` is the row under the text's last row of a capital or digit.
  void draw(Canvas& canvas, int x, int baseline, const std::string& text, Align align,
            Pixel colour) const {
    if (useFont_ && draw_(canvas.rgb.data(), canvas.width, canvas.height, x, baseline, text.c_str(),
                          kFontSize, &colour.x, static_cast<int>(align)))
      return;
    const int w = static_cast<int>(text.size()) * 6 - 1;
    int left = align == Align::Left ? x : align == Align::Right ? x - w : x - w / 2;
    for (const char character : text) {
      for (const Glyph& glyph : kGlyphs) {
        if (glyph.character != character) continue;
        for (int row = 0; row < 7; ++row)
          for (int column = 0; column < 5; ++column)
            if (glyph.rows[row] & (0x10 >> column))
              canvas.set(left + column, baseline - 7 + row, colour);
      }
      left += 6;
    }
  }

 private:
  int (*width_)(const char*, int) = nullptr;
  int (*draw_)(float*, int, int, int, int, const char*, int, const float*, int) = nullptr;
  bool useFont_ = false;
};

// ---- Shading. ----------------------------------------------------------------------------------

}  // namespace

bool isFloatFormat(const std::string& path) {
  const std::string extension = path.substr(path.find_last_of('.') + 1);
  return extension == "exr" || extension == "tif" || extension == "tiff" || extension == "hdr";
}

Pixel shadedColour(const Camera& camera, size_t index, const FramePixel& result) {
  const int width = camera.width;
  const glm::dvec3 direction =
      camera.primaryRay(static_cast<int>(index % width), static_cast<int>(index / width)).direction;
  if (!result.hit) return Pixel(0.08f, 0.09f, 0.12f);
  glm::dvec3 normal = glm::normalize(result.normal);
  if (glm::dot(normal, direction) > 0) normal = -normal;  // the face the ray met looks back at it
  const glm::dvec3 light = glm::normalize(glm::dvec3(0.45, 0.8, -0.4));
  const float lambert = static_cast<float>(std::max(0.0, glm::dot(normal, light)));
  return Pixel(0.86f, 0.80f, 0.68f) *
         (0.22f * result.ambientOpen + 0.78f * lambert * result.lightOpen);
}

namespace {

// Matplotlib's viridis (perceptually uniform, readable in grey and by colour-blind viewers),
// sampled at 17 points of its 256-entry table; t in [0, 1].
Pixel viridis(float t) {
  static constexpr float kTable[17][3] = {
      {0.2670f, 0.0049f, 0.3294f}, {0.2823f, 0.0950f, 0.4173f}, {0.2788f, 0.1755f, 0.4834f},
      {0.2590f, 0.2515f, 0.5247f}, {0.2297f, 0.3224f, 0.5457f}, {0.1994f, 0.3876f, 0.5546f},
      {0.1727f, 0.4488f, 0.5579f}, {0.1490f, 0.5081f, 0.5573f}, {0.1276f, 0.5669f, 0.5506f},
      {0.1201f, 0.6222f, 0.5349f}, {0.1539f, 0.6802f, 0.5042f}, {0.2394f, 0.7356f, 0.4557f},
      {0.3607f, 0.7860f, 0.3878f}, {0.5063f, 0.8288f, 0.3004f}, {0.6681f, 0.8620f, 0.1963f},
      {0.8353f, 0.8860f, 0.1026f}, {0.9932f, 0.9062f, 0.1439f}};
  const float position = std::clamp(t, 0.0f, 1.0f) * 16.0f;
  const int low = std::min(static_cast<int>(position), 15);
  const float fraction = position - static_cast<float>(low);
  return glm::mix(Pixel(kTable[low][0], kTable[low][1], kTable[low][2]),
                  Pixel(kTable[low + 1][0], kTable[low + 1][1], kTable[low + 1][2]), fraction);
}

// Misses: the thesis's red, from pale pink (cheap) to dark red (expensive).
Pixel missColour(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return Pixel(1.0f - 0.45f * t, 0.82f * (1.0f - t), 0.82f * (1.0f - t));
}

// Where a cost lies on the scale, 0 (cheapest of the frame) to 1 (dearest): logarithmic, as a
// frame's costs are skewed (menger: hits median 23 cycles, maximum 328), so a linear scale would
// paint nearly every hit in the same dark colour.
struct CostScale {
  uint32_t low = 0;
  uint32_t high = 0;

  float operator()(uint32_t cost) const {
    if (high == low) return 0.5f;
    return static_cast<float>((std::log1p(static_cast<double>(cost)) - std::log1p(low)) /
                              (std::log1p(static_cast<double>(high)) - std::log1p(low)));
  }
};

struct Label {
  uint32_t cost;
  int x;  // the tick's column
  Align align;
  int left, right;  // the label's columns
};

// Labels of the cost scale: both ends, then round values (1, 2, 5 x 10^k first, then other
// multiples of powers of ten) wherever they fit without crowding, at most 9 in all.
std::vector<Label> scaleLabels(const CostScale& scale, int x0, int rampWidth,
                               const TextPainter& text) {
  const auto column = [&](uint32_t cost) {
    return x0 + static_cast<int>(std::lround(scale(cost) * (rampWidth - 1)));
  };
  const auto make = [&](uint32_t cost, Align align) {
    const int x = column(cost);
    const int w = text.width(std::to_string(cost));
    const int left = align == Align::Left ? x : align == Align::Right ? x - w : x - w / 2;
    return Label{cost, x, align, left, left + w};
  };
  std::vector<Label> labels{make(scale.low, Align::Left)};
  if (scale.high == scale.low) return labels;
  labels.push_back(make(scale.high, Align::Right));
  std::vector<std::pair<int, uint32_t>> candidates;  // (priority, cost)
  for (uint64_t power = 1; power <= scale.high; power *= 10)
    for (uint64_t multiple = 1; multiple <= 9; ++multiple) {
      const uint64_t cost = multiple * power;
      if (cost <= scale.low || cost >= scale.high) continue;
      const bool round = multiple == 1 || multiple == 2 || multiple == 5;
      candidates.emplace_back((round ? 0 : 100) - static_cast<int>(std::log10(power)),
                              static_cast<uint32_t>(cost));
    }
  std::sort(candidates.begin(), candidates.end());
  constexpr int kClearance = 8;
  for (const auto& [priority, cost] : candidates) {
    if (labels.size() >= 9) break;
    const Label label = make(cost, Align::Centre);
    const bool fits = std::none_of(labels.begin(), labels.end(), [&](const Label& other) {
      return label.left < other.right + kClearance && other.left < label.right + kClearance;
    });
    if (fits) labels.push_back(label);
  }
  return labels;
}

}  // namespace

RenderedFrame::RenderedFrame(const Camera& camera) : camera(camera), pixels(camera.pixelCount()) {}

void RenderedFrame::place(uint32_t id, const FramePixel& pixel) {
  if (id >= pixels.size())
    throw std::runtime_error("result for job " + std::to_string(id) + " lies outside the " +
                             std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                             " frame");
  pixels[id] = pixel;
}

RenderedFrame RenderedFrame::fromResults(const Camera& camera, const FixedFormat& format,
                                         const std::vector<TraversalResult>& results) {
  RenderedFrame frame(camera);
  for (const TraversalResult& result : results) frame.place(result.id(), svoPixel(format, result));
  return frame;
}

FramePixel svoPixel(const FixedFormat& format, const TraversalResult& result) {
  FramePixel pixel{result.hit, format.toDouble(result.tHit), result.cost, glm::dvec3(0.0)};
  pixel.normal[result.normal[0] ? 0 : result.normal[1] ? 1 : 2] = 1.0;  // the face's axis
  return pixel;
}

void writeRgbImage(const std::string& path, int width, int height, const std::vector<float>& rgb) {
  writeImageFile(path, width, height, 3, rgb, false);
}

void writeShadedImage(const RenderedFrame& frame, const std::string& path) {
  // A row at a time (RowImage): the frame's pixels are held already, its image need not be.
  const size_t width = static_cast<size_t>(frame.camera.width);
  RowImage image(path, frame.camera.width, frame.camera.height, 3, false);
  std::vector<float> row(width * 3);
  for (size_t first = 0; first < frame.pixels.size(); first += width) {
    for (size_t x = 0; x < width; ++x) {
      const Pixel colour =
          glm::clamp(shadedColour(frame.camera, first + x, frame.pixels[first + x]), 0.0f, 1.0f);
      std::copy(&colour.x, &colour.x + 3, &row[x * 3]);
    }
    image.write(row.data(), 1);
  }
  image.commit();
}

void writePrecisionImage(const Camera& camera, const std::vector<PrecisionVerdict>& verdicts,
                         const std::string& path) {
  static const std::array<Pixel, 5> colours = {Pixel(0.08f),                 // BothMiss
                                               Pixel(0.45f),                 // Agree
                                               Pixel(0.20f, 0.50f, 1.00f),   // FalseHit
                                               Pixel(1.00f, 0.20f, 0.20f),   // MissedHit
                                               Pixel(1.00f, 0.85f, 0.10f)};  // DifferentVoxel
  Canvas canvas(camera.width, camera.height, colours[0]);
  for (size_t i = 0; i < verdicts.size(); ++i)
    canvas.set(static_cast<int>(i % camera.width), static_cast<int>(i / camera.width),
               colours[static_cast<size_t>(verdicts[i])]);
  writeImageFile(path, canvas.width, canvas.height, 3, canvas.rgb, false);
}

void writeCostImage(const RenderedFrame& frame, const std::string& path) {
  std::vector<CostSample> samples;
  samples.reserve(frame.pixels.size());
  for (const FramePixel& pixel : frame.pixels) samples.push_back(CostSample{pixel.cost, pixel.hit});
  writeCostImage(frame.camera, samples, path);
}

// The frame's rows, then the scale strip under it: two ramps (hits, misses) over the frame's
// cost range, tick marks and labels in cycles; a legend column on the left when the frame is
// wide enough. Written row by row (only a row of the frame is coloured at a time).
void writeCostImage(const Camera& camera, const std::vector<CostSample>& samples,
                    const std::string& path) {
  const int width = camera.width;
  const int height = camera.height;
  CostScale scale{std::numeric_limits<uint32_t>::max(), 0};
  for (const CostSample& sample : samples) {
    scale.low = std::min(scale.low, sample.cost);
    scale.high = std::max(scale.high, sample.cost);
  }
  if (samples.empty()) scale.low = scale.high = 0;

  constexpr int kPad = 4, kRamp = 10, kGap = 2, kTick = 3, kStrip = 46;
  const bool withScale = width >= 96;
  const Pixel background(0.12f), ink(0.92f);
  RowImage image(path, width, height + (withScale ? kStrip : 0), 3, false);
  Canvas row(width, 1, background);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const CostSample& sample = samples[static_cast<size_t>(y) * width + x];
      const float t = scale(sample.cost);
      row.set(x, 0, sample.hit ? viridis(t) : missColour(t));
    }
    image.write(row.rgb.data(), 1);
  }
  if (withScale) {
    Canvas strip(width, kStrip, background);
    const TextPainter text;
    const bool withLegend = width >= 200;
    const int legendWidth =
        withLegend ? std::max({text.width("hit"), text.width("miss"), text.width("cycles")}) + 6
                   : 0;
    const int x0 = kPad + legendWidth;
    const int rampWidth = width - kPad - x0;
    const int hitY = kPad;
    const int missY = hitY + kRamp + kGap;
    const int tickY = missY + kRamp;
    const int labelBaseline = tickY + kTick + 10;
    for (int x = 0; x < rampWidth; ++x) {
      const float t = static_cast<float>(x) / static_cast<float>(std::max(rampWidth - 1, 1));
      strip.fill(x0 + x, hitY, 1, kRamp, viridis(t));
      strip.fill(x0 + x, missY, 1, kRamp, missColour(t));
    }
    if (withLegend) {
      text.draw(strip, kPad, hitY + kRamp - 1, "hit", Align::Left, ink);
      text.draw(strip, kPad, missY + kRamp - 1, "miss", Align::Left, ink);
      text.draw(strip, kPad, labelBaseline, "cycles", Align::Left, ink);
    }
    for (const Label& label : scaleLabels(scale, x0, rampWidth, text)) {
      strip.fill(label.x, tickY, 1, kTick, ink);
      text.draw(strip, label.x, labelBaseline, std::to_string(label.cost), label.align, ink);
    }
    image.write(strip.rgb.data(), kStrip);
  }
  image.commit();
}

float depthSample(const FramePixel& pixel) {
  return pixel.hit ? static_cast<float>(pixel.t) : std::numeric_limits<float>::quiet_NaN();
}

void writeDepthImage(const RenderedFrame& frame, const std::string& path) {
  std::vector<float> samples;
  samples.reserve(frame.pixels.size());
  for (const FramePixel& pixel : frame.pixels) samples.push_back(depthSample(pixel));
  writeDepthImage(frame.camera, samples, path);
}

void writeDepthImage(const Camera& camera, const std::vector<float>& samples,
                     const std::string& path) {
  float nearest = std::numeric_limits<float>::max();
  float farthest = std::numeric_limits<float>::lowest();
  for (float t : samples) {
    if (std::isnan(t)) continue;
    nearest = std::min(nearest, t);
    farthest = std::max(farthest, t);
  }
  const bool floatFile = isFloatFormat(path);
  const float range = std::max(farthest - nearest, 1e-6f);
  RowImage image(path, camera.width, camera.height, 1, floatFile);
  std::vector<float> row(static_cast<size_t>(camera.width));
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const float t = samples[static_cast<size_t>(y) * camera.width + x];
      row[static_cast<size_t>(x)] = std::isnan(t) ? 0.0f
                                    : floatFile   ? t
                                                  : 1.0f - 0.85f * (t - nearest) / range;
    }
    image.write(row.data(), 1);
  }
  image.commit();
}

}  // namespace rtu
