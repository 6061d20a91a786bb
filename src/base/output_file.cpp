#include "base/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <vector>

#include "base/temporary_files.h"

namespace rtu {
namespace {

namespace fs = std::filesystem;

std::string cause(int error) { return std::strerror(error); }

// The file `path` names: links followed, so that the link itself is kept (a link to a missing
// file names the file to create). None for a link through /proc (/dev/stdout, /dev/fd/3): a
// descriptor of this process, written in place.
std::optional<fs::path> followLinks(const std::string& path) {
  constexpr int kMaxLinks = 40;  // as the kernel's ELOOP
  fs::path current = path;
  std::error_code error;
  for (int links = 0; fs::is_symlink(fs::symlink_status(current, error)); ++links) {
    fs::path next = fs::read_symlink(current, error);
    if (error || links == kMaxLinks)
      throw std::runtime_error("cannot create '" + path + "': too many symbolic links");
    if (next.is_relative()) next = current.parent_path() / next;
    if (next.string().rfind("/proc/", 0) == 0) return std::nullopt;
    current = next;
  }
  return current;
}

// A new file's permissions as the process would create it (0666 less the umask); a replaced
// file keeps its own.
mode_t modeFor(const fs::file_status& existing) {
  if (fs::is_regular_file(existing)) return static_cast<mode_t>(existing.permissions());
  static const mode_t mask = [] {  // umask() can only be read by setting it
    const mode_t old = ::umask(022);
    ::umask(old);
    return old;
  }();
  return 0666 & ~mask;
}

}  // namespace

// A stream buffer over a file descriptor that keeps the first write error (errno) for commit().
class OutputFile::Buffer : public std::streambuf {
 public:
  explicit Buffer(int fd) : fd_(fd), space_(size_t{1} << 16) { reset(); }
  ~Buffer() override {
    if (fd_ >= 0) ::close(fd_);
  }
  // The first write error (errno), or 0.
  int error() const { return error_; }
  // Writes what is buffered and closes the file; the first error, or 0.
  int close() {
    drain();
    if (::close(fd_) != 0 && error_ == 0) error_ = errno;
    fd_ = -1;
    return error_;
  }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  void reset() { setp(space_.data(), space_.data() + space_.size()); }
  bool drain() {
    const char* data = pbase();
    size_t left = static_cast<size_t>(pptr() - pbase());
    while (left > 0 && error_ == 0) {
      const ssize_t written = ::write(fd_, data, left);
      if (written < 0 && errno == EINTR) continue;
      if (written < 0) error_ = errno;
      if (written <= 0) break;
      data += written;
      left -= static_cast<size_t>(written);
    }
    if (left > 0 && error_ == 0) error_ = EIO;  // write() returned 0
    reset();
    return error_ == 0;
  }

  int fd_;
  int error_ = 0;
  std::vector<char> space_;
};

OutputFile::OutputFile(const std::string& path) : path_(path) {
  const std::optional<fs::path> followed = followLinks(path);
  const fs::path target = followed.value_or(fs::path(path));
  target_ = target.string();
  std::error_code error;
  const fs::file_status status = fs::status(target, error);
  int fd = -1;
  inPlace_ = !followed || (fs::exists(status) && !fs::is_regular_file(status));
  if (inPlace_) {
    writePath_ = target_;
    fd = ::open(target_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  } else {
    removeStaleTemporaries(target);
    writePath_ = temporaryPattern(target);
    const int suffix = static_cast<int>(target.extension().string().size());
    fd = ::mkostemps(writePath_.data(), suffix, O_CLOEXEC);
    if (fd >= 0) {
      registration_ = std::make_unique<TemporaryRegistration>(writePath_);
      ::fchmod(fd, modeFor(status));
    }
  }
  if (fd < 0) throw std::runtime_error("cannot create '" + path + "': " + cause(errno));
  buffer_ = std::make_unique<Buffer>(fd);
  stream_ = std::make_unique<std::ostream>(buffer_.get());
}

OutputFile::~OutputFile() {
  if (!committed_ && !inPlace_) ::unlink(writePath_.c_str());
  registration_.reset();
}

std::ostream& OutputFile::stream() { return *stream_; }

void OutputFile::commit() {
  stream_->flush();
  const int error = buffer_->close();
  if (error != 0) fail(cause(error));
  if (!*stream_) fail("a write failed");
  if (!inPlace_ && std::rename(writePath_.c_str(), target_.c_str()) != 0) fail(cause(errno));
  committed_ = true;
}

void OutputFile::throwIfFailed() {
  stream_->flush();
  if (buffer_->error() != 0) fail(cause(buffer_->error()));
}

void OutputFile::fail(const std::string& reason) const {
  throw std::runtime_error("cannot write '" + path_ + "': " + reason);
}

void writeTextFile(const std::string& path, const std::string& text) {
  OutputFile file(path);
  file.stream() << text;
  file.commit();
}

void checkStandardOutput() {
  std::cout.flush();
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout)
    throw std::runtime_error("cannot write standard output" +
                             (errno != 0 ? ": " + cause(errno) : std::string()));
}

}  // namespace rtu
