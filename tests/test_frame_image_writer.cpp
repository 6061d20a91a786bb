// Issue 33: render's images written as the frame's results leave the run (FrameImageWriter): the
// same files as images of the whole frame, with only the rows the results in flight touch held.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "app/frame_image_writer.h"
#include "app/frame_images.h"

namespace rtu {
namespace {

namespace fs = std::filesystem;

struct ImageFolder {
  fs::path path;
  ImageFolder() {
    std::string name = (fs::temp_directory_path() / "rtusim-images-XXXXXX").string();
    path = ::mkdtemp(name.data());
  }
  ~ImageFolder() { fs::remove_all(path); }
  std::string file(const std::string& name) const { return (path / name).string(); }
};

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A frame of hits and misses of assorted costs, depths and normals.
RenderedFrame madeUpFrame(int width, int height) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  RenderedFrame frame(camera);
  std::mt19937 random(7);
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    FramePixel& pixel = frame.pixels[i];
    pixel.hit = random() % 3 != 0;
    pixel.cost = 10 + random() % 300;
    pixel.t = pixel.hit ? 1.0 + (random() % 1000) / 100.0 : 0.0;
    pixel.normal = glm::dvec3(random() % 2, 1.0, random() % 3);
  }
  return frame;
}

// The pixels' ids in job order, each moved by up to `window` places (results leave the RTU
// nearly in order).
std::vector<uint32_t> nearlyInOrder(size_t count, size_t window) {
  std::vector<uint32_t> ids(count);
  for (size_t i = 0; i < count; ++i) ids[i] = static_cast<uint32_t>(i);
  std::mt19937 random(11);
  for (size_t start = 0; start < count; start += window)
    std::shuffle(ids.begin() + static_cast<std::ptrdiff_t>(start),
                 ids.begin() + static_cast<std::ptrdiff_t>(std::min(count, start + window)),
                 random);
  return ids;
}

}  // namespace

TEST_CASE("Frame images written as results come equal the whole frame's\\, few rows held",
          "[frame_images]") {
  const std::string extension = GENERATE(as<std::string>{}, "png", "exr");
  CAPTURE(extension);
  ImageFolder folder;
  const RenderedFrame frame = madeUpFrame(160, 120);  // the cost image's scale strip too
  writeShadedImage(frame, folder.file("whole." + extension));
  writeDepthImage(frame, folder.file("whole_depth." + extension));
  writeCostImage(frame, folder.file("whole_cost." + extension));

  FrameImageWriter writer(frame.camera, FrameImagePaths{folder.file("rows." + extension),
                                                        folder.file("rows_depth." + extension),
                                                        folder.file("rows_cost." + extension)});
  for (uint32_t id : nearlyInOrder(frame.pixels.size(), 200)) writer.place(id, frame.pixels[id]);
  writer.finish();
  for (const std::string image : {"", "_depth", "_cost"}) {
    INFO(image);
    const std::string whole = bytesOf(folder.file("whole" + image + "." + extension));
    CHECK(!whole.empty());
    CHECK(bytesOf(folder.file("rows" + image + "." + extension)) == whole);
  }
  // 200 pixels in flight span at most three rows of 160, and the row being filled.
  CHECK(writer.mostRowsHeld() >= 2);
  CHECK(writer.mostRowsHeld() <= 4);
  CHECK(std::distance(fs::directory_iterator(folder.path), {}) == 6);  // no temporary left
}

TEST_CASE("A frame image written as results come leaves nothing when not finished",
          "[frame_images]") {
  ImageFolder folder;
  const RenderedFrame frame = madeUpFrame(40, 30);
  {
    FrameImageWriter writer(frame.camera, FrameImagePaths{folder.file("a.png"), "", ""});
    for (uint32_t id = 0; id < 600; ++id) writer.place(id, frame.pixels[id]);
  }
  CHECK(fs::is_empty(folder.path));
}

}  // namespace rtu
