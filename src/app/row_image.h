#pragma once
// An image file written row by row, top to bottom, under the output rule (base/output_file.h):
// a PNG file's rows are encoded by OpenImageIO as they come and its bytes written through the
// checked temporary file at once; an EXR or TIFF file's rows are written by OpenImageIO's scanline
// writes into the temporary file (their writers seek back: checked by OpenImageIO's status), so
// that only a row need be held, the files equal to those written whole. Other formats (JPEG, ...)
// hold the rows and are written whole by commit() (writeImageFile).

#include <memory>
#include <string>
#include <vector>

#include "base/output_file.h"

namespace rtu {

class RowImage {
 public:
  // `path`'s format, for `width` x `height` pixels of `channels` floats (in [0, 1] for 8-bit
  // samples; 32-bit float samples when `floatFile`). Throws std::runtime_error naming the file.
  RowImage(const std::string& path, int width, int height, int channels, bool floatFile);
  // Without commit(): nothing at the path changes (the temporary file is removed).
  ~RowImage();
  RowImage(const RowImage&) = delete;
  RowImage& operator=(const RowImage&) = delete;

  // The next `rows` rows: width x channels floats each.
  void write(const float* data, int rows);
  // After the last row: the file complete, renamed into place.
  void commit();

  // Bytes a pixel an image of `path`'s format holds until commit(): 0 for the formats written as
  // the rows come (PNG, EXR, TIFF), `channels` floats for the others.
  static size_t heldBytesPerPixel(const std::string& path, int channels);
  // Whether the rows are encoded as they come (PNG, EXR, TIFF) rather than held.
  bool streams() const { return writer_ != nullptr; }

 private:
  // Throws the output file's own write error when there was one, else `cause`.
  [[noreturn]] void fail(const std::string& cause);

  std::string path_;
  int width_, height_, channels_;
  bool floatFile_;
  int rowsWritten_ = 0;
  std::unique_ptr<OutputFile> file_;  // a streamed image's
  void* writer_ = nullptr;            // the plugin's, for a streamed image
  std::vector<float> held_;           // the rows of an image written whole
};

}  // namespace rtu
