#include "app/row_image.h"

#include <cctype>
#include <ostream>
#include <stdexcept>

#include "app/frame_images.h"
#include "base/plugin_loader.h"

namespace rtu {
namespace {

constexpr const char* kImagesModule = "librtusim_images.so";
constexpr const char* kImagesPurpose = "needed to write images";

using OpenFunction = const char*(const char*, const char*, int, int, int, int,
                                 int (*)(void*, const void*, size_t), void*, void**);
using RowsFunction = const char*(void*, int, int, const float*);
using CloseFunction = const char*(void*, int);

CloseFunction* closeFunction() {
  static CloseFunction* const close =
      pluginFunction<CloseFunction>(kImagesModule, "rtusim_images_close", kImagesPurpose);
  return close;
}

// The encoder's bytes into the output file's checked stream; 0 once a write failed.
int writeBytes(void* file, const void* bytes, size_t size) {
  std::ostream& stream = static_cast<OutputFile*>(file)->stream();
  stream.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
  return stream ? 1 : 0;
}

// How a format's rows are written as they come: PNG's encoded bytes in order through the checked
// stream; EXR's and TIFF's by OpenImageIO into the temporary file (their writers seek back), with
// scanline writes. Other formats hold their rows.
enum class RowWriting { InOrder, IntoFile, Held };

RowWriting rowWriting(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos) return RowWriting::Held;
  std::string extension = path.substr(dot + 1);
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == "png") return RowWriting::InOrder;
  if (extension == "exr" || extension == "tif" || extension == "tiff") return RowWriting::IntoFile;
  return RowWriting::Held;
}

}  // namespace

RowImage::RowImage(const std::string& path, int width, int height, int channels, bool floatFile)
    : path_(path), width_(width), height_(height), channels_(channels), floatFile_(floatFile) {
  const RowWriting writing = rowWriting(path);
  if (writing == RowWriting::Held) {
    held_.reserve(static_cast<size_t>(width) * static_cast<size_t>(height) *
                  static_cast<size_t>(channels));
    return;
  }
  static OpenFunction* const open =
      pluginFunction<OpenFunction>(kImagesModule, "rtusim_images_open", kImagesPurpose);
  file_ = std::make_unique<OutputFile>(path);
  const bool inOrder = writing == RowWriting::InOrder;
  const char* error = open(path.c_str(), file_->writePath().c_str(), width, height, channels,
                           floatFile, inOrder ? writeBytes : nullptr, file_.get(), &writer_);
  if (error) fail(error);
}

size_t RowImage::heldBytesPerPixel(const std::string& path, int channels) {
  return rowWriting(path) == RowWriting::Held ? static_cast<size_t>(channels) * sizeof(float) : 0;
}

RowImage::~RowImage() {
  if (writer_) closeFunction()(writer_, 0);
}

void RowImage::write(const float* data, int rows) {
  if (rowsWritten_ + rows > height_)
    throw std::logic_error("RowImage: more rows than the image of '" + path_ + "' has");
  const size_t values =
      static_cast<size_t>(rows) * static_cast<size_t>(width_) * static_cast<size_t>(channels_);
  if (writer_) {
    static RowsFunction* const writeRows =
        pluginFunction<RowsFunction>(kImagesModule, "rtusim_images_write_rows", kImagesPurpose);
    if (const char* error = writeRows(writer_, rowsWritten_, rows, data)) fail(error);
  } else {
    held_.insert(held_.end(), data, data + values);
  }
  rowsWritten_ += rows;
}

void RowImage::commit() {
  if (rowsWritten_ != height_)
    throw std::logic_error("RowImage: '" + path_ + "' committed before its last row");
  if (!writer_) return writeImageFile(path_, width_, height_, channels_, held_, floatFile_);
  void* writer = writer_;
  writer_ = nullptr;
  if (const char* error = closeFunction()(writer, 1)) fail(error);
  file_->commit();
}

void RowImage::fail(const std::string& cause) {
  file_->throwIfFailed();
  file_->fail(cause);
}

}  // namespace rtu
