// librtusim_images.so: the OpenImageIO half of frame_images.cpp, loaded with dlopen on first use
// so that only commands writing an image load OpenImageIO and its many dependencies. It sees
// plain float pixel buffers only, no rtusim type.

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include "base/plugin_entry.h"

namespace {

// The font of the scale labels: DejaVu Sans (Debian fonts-dejavu-core) when installed, else
// whatever OpenImageIO finds by default.
std::string fontName() {
  static const std::string dejavu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  std::error_code error;
  return std::filesystem::exists(dejavu, error) ? dejavu : std::string();
}

// The encoded bytes handed on as OpenImageIO writes them, in order: to the caller's checked
// output file. A write elsewhere than at the end (a format that seeks back) fails.
class CallbackOutput final : public OIIO::Filesystem::IOProxy {
 public:
  using WriteFunction = int (*)(void* context, const void* bytes, size_t size);

  CallbackOutput(WriteFunction write, void* context)
      : IOProxy("", Write), write_(write), context_(context) {}
  const char* proxytype() const override { return "rtusim"; }
  size_t write(const void* bytes, size_t size) override {
    if (size > 0 && !write_(context_, bytes, size)) return 0;
    m_pos += static_cast<int64_t>(size);
    return size;
  }
  size_t pwrite(const void* bytes, size_t size, int64_t offset) override {
    return offset == m_pos ? write(bytes, size) : 0;
  }
  bool seek(int64_t offset) override { return offset == m_pos; }
  size_t size() const override { return static_cast<size_t>(m_pos); }

 private:
  WriteFunction write_;
  void* context_;
};

// The encoded bytes written where OpenImageIO puts them, into the file `path` (formats that seek
// back: EXR, TIFF), every write checked: the first failure's cause is kept (failure()) and fails
// the writes after it.
class FileOutput final : public OIIO::Filesystem::IOProxy {
 public:
  explicit FileOutput(const std::string& path)
      : IOProxy(path, Write),
        fd_(::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666)) {
    if (fd_ < 0) failure_ = std::strerror(errno);
  }
  ~FileOutput() override {
    if (fd_ >= 0) ::close(fd_);
  }
  const char* proxytype() const override { return "rtusim-file"; }
  size_t write(const void* bytes, size_t size) override {
    const size_t written = pwrite(bytes, size, m_pos);
    m_pos += static_cast<int64_t>(written);
    return written;
  }
  size_t pwrite(const void* bytes, size_t size, int64_t offset) override {
    const char* data = static_cast<const char*>(bytes);
    for (size_t done = 0; done < size;) {
      if (!failure_.empty()) return 0;
      const ssize_t n =
          ::pwrite(fd_, data + done, size - done, offset + static_cast<int64_t>(done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        failure_ = n < 0 ? std::strerror(errno) : "nothing written";
        return 0;
      }
      done += static_cast<size_t>(n);
    }
    end_ = std::max(end_, offset + static_cast<int64_t>(size));
    return size;
  }
  size_t size() const override { return static_cast<size_t>(end_); }
  // Closes the file; the first failure's cause, or "".
  const std::string& finish() {
    if (fd_ >= 0 && ::close(fd_) != 0 && failure_.empty()) failure_ = std::strerror(errno);
    fd_ = -1;
    return failure_;
  }
  const std::string& failure() const { return failure_; }

 private:
  int fd_;
  int64_t end_ = 0;
  std::string failure_;
};

// An image written row by row (rtusim_images_open): through `proxy` or into `file`.
// The output is destroyed first: closing, it may still write to them.
struct ImageRowWriter {
  CallbackOutput proxy;
  std::unique_ptr<FileOutput> file;
  std::unique_ptr<OIIO::ImageOutput> output;
};

// Why a writer failed: its file's write error (the cause OpenImageIO's message would hide), else
// OpenImageIO's message.
std::string failure(ImageRowWriter& writer) {
  if (writer.file && !writer.file->failure().empty()) return writer.file->failure();
  return "OpenImageIO: " + writer.output->geterror();
}

}  // namespace

RTUSIM_PLUGIN_ABI_ENTRY

// Encodes `width` x `height` pixels of `channels` floats each (rows top to bottom) in the format
// `path`'s extension names: 32-bit float samples when `floatFile`, else 8-bit. Into memory when
// the format can (*bytes and *size then hold the file, valid until the thread's next call), so
// that the caller checks every write; else into the file `writePath` (*bytes null), checked by
// OpenImageIO's own status only. Returns nullptr, or the error message (valid as long).
RTUSIM_PLUGIN_EXPORT const char* rtusim_images_write(const char* path, const char* writePath,
                                                     int width, int height, int channels,
                                                     const float* data, int floatFile,
                                                     const unsigned char** bytes, size_t* size) {
  thread_local std::vector<unsigned char> encoded;
  *bytes = nullptr;
  *size = 0;
  return rtu::pluginCall([&]() -> std::string {
    auto output = OIIO::ImageOutput::create(path);
    if (!output) return "OpenImageIO: " + OIIO::geterror();
    encoded.clear();
    OIIO::Filesystem::IOVecOutput memory(encoded);
    const bool inMemory = output->supports("ioproxy") && output->set_ioproxy(&memory);
    const OIIO::ImageSpec spec(width, height, channels,
                               floatFile ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!output->open(writePath, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, data) ||
        !output->close())
      return "OpenImageIO: " + output->geterror();
    if (inMemory) {
      *bytes = encoded.data();
      *size = encoded.size();
    }
    return {};
  });
}

// Opens `path`'s format for `width` x `height` pixels of `channels` floats each (32-bit float
// samples when `floatFile`, else 8-bit), written row by row as rtusim_images_write_rows hands them
// over (OpenImageIO's scanline writes). With `write`, each encoded piece goes to `write` (which
// returns 0 on a failed write) as OpenImageIO makes it: only formats that write their bytes in
// order qualify (PNG). Without it, OpenImageIO writes the file `writePath` itself (formats that
// seek back: EXR, TIFF), checked by its own status only. *handle is the writer to pass on, and to
// rtusim_images_close whatever happens. Returns nullptr, or the error message (valid until the
// thread's next call).
RTUSIM_PLUGIN_EXPORT const char* rtusim_images_open(const char* path, const char* writePath,
                                                    int width, int height, int channels,
                                                    int floatFile,
                                                    int (*write)(void*, const void*, size_t),
                                                    void* context, void** handle) {
  *handle = nullptr;
  return rtu::pluginCall([&]() -> std::string {
    auto output = OIIO::ImageOutput::create(path);
    if (!output) return "OpenImageIO: " + OIIO::geterror();
    auto* writer = new ImageRowWriter{CallbackOutput(write, context),
                                      write ? nullptr : std::make_unique<FileOutput>(writePath),
                                      std::move(output)};
    *handle = writer;
    if (writer->file && !writer->file->failure().empty()) return writer->file->failure();
    OIIO::Filesystem::IOProxy* proxy =
        writer->file ? static_cast<OIIO::Filesystem::IOProxy*>(writer->file.get()) : &writer->proxy;
    if (!writer->output->supports("ioproxy") || !writer->output->set_ioproxy(proxy))
      return "OpenImageIO: the format of '" + std::string(path) + "' is not written row by row";
    const OIIO::ImageSpec spec(width, height, channels,
                               floatFile ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    if (!writer->output->open(path, spec)) return failure(*writer);
    return {};
  });
}

// The next `rows` rows of the image `handle` opened, top to bottom.
RTUSIM_PLUGIN_EXPORT const char* rtusim_images_write_rows(void* handle, int firstRow, int rows,
                                                          const float* data) {
  return rtu::pluginCall([&]() -> std::string {
    auto* writer = static_cast<ImageRowWriter*>(handle);
    if (!writer->output->write_scanlines(firstRow, firstRow + rows, 0, OIIO::TypeDesc::FLOAT,
                                         data) ||
        (writer->file && !writer->file->failure().empty()))
      return failure(*writer);
    return {};
  });
}

// Closes the image (complete when `finish`) and frees the writer.
RTUSIM_PLUGIN_EXPORT const char* rtusim_images_close(void* handle, int finish) {
  return rtu::pluginCall([&]() -> std::string {
    std::unique_ptr<ImageRowWriter> writer(static_cast<ImageRowWriter*>(handle));
    if (!writer) return {};
    if (!finish) return {};
    if (!writer->output->close()) return failure(*writer);
    if (writer->file && !writer->file->finish().empty()) return writer->file->failure();
    return {};
  });
}

// Whether OpenImageIO can write the format `path`'s extension names, without creating the file.
// Returns nullptr, or the error message (valid until the thread's next call).
RTUSIM_PLUGIN_EXPORT const char* rtusim_images_format_error(const char* path) {
  return rtu::pluginCall([&]() -> std::string {
    if (!OIIO::ImageOutput::create(path)) return "OpenImageIO: " + OIIO::geterror();
    return {};
  });
}

// Width in pixels of `text` at `fontSize` pixels, or -1 when no font can be loaded.
RTUSIM_PLUGIN_EXPORT int rtusim_images_text_width(const char* text, int fontSize) {
  try {
    const OIIO::ROI size = OIIO::ImageBufAlgo::text_size(text, fontSize, fontName());
    return size.defined() ? size.width() : -1;
  } catch (...) {
    return -1;
  }
}

// Draws `text` (anti-aliased, in `colour`, one float per channel) into the RGB float buffer
// `pixels` of `width` x `height`, its baseline at row `y`, starting at column `x` (align 0),
// ending there (1) or centred on it (2). Returns 1, or 0 when the text could not be rendered.
RTUSIM_PLUGIN_EXPORT int rtusim_images_draw_text(float* pixels, int width, int height, int x, int y,
                                                 const char* text, int fontSize,
                                                 const float* colour, int align) {
  try {
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf image(spec, pixels);
    const OIIO::ImageBufAlgo::TextAlignX alignX = align == 1 ? OIIO::ImageBufAlgo::TextAlignX::Right
                                                  : align == 2
                                                      ? OIIO::ImageBufAlgo::TextAlignX::Center
                                                      : OIIO::ImageBufAlgo::TextAlignX::Left;
    return OIIO::ImageBufAlgo::render_text(image, x, y, text, fontSize, fontName(), {colour, 3},
                                           alignX)
               ? 1
               : 0;
  } catch (...) {
    return 0;
  }
}
