#include "base/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <stdexcept>

#include "base/work_phase.h"

namespace rtu {

namespace {

std::string fileType(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file";
}

std::string named(const std::string& what, const std::string& path) {
  return (what.empty() ? "" : what + " ") + "'" + path + "'";
}

}  // namespace

// stat before open: opening a FIFO blocks until a writer comes. A path swapped for a FIFO
// between the two calls can still block; that needs someone racing rtusim on purpose.
uint64_t inputFileBytes(const std::string& path, const std::string& what) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0)
    throw std::runtime_error("cannot open " + named(what, path) + ": " + std::strerror(errno));
  if (!S_ISREG(status.st_mode))
    throw std::runtime_error(named(what, path) + " is not a regular file (" +
                             fileType(status.st_mode) + ")");
  return static_cast<uint64_t>(status.st_size);
}

std::ifstream openInputFile(const std::string& path, const std::string& what, uint64_t& bytes) {
  bytes = inputFileBytes(path, what);
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot open " + named(what, path));
  return file;
}

std::ifstream openInputFileIfAny(const std::string& path, const std::string& what) {
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, error))) return {};
  uint64_t bytes = 0;
  return openInputFile(path, what, bytes);
}

std::string readInputFile(const std::string& path, const std::string& what, uint64_t maxBytes) {
  uint64_t bytes = 0;
  std::ifstream file = openInputFile(path, what, bytes);
  if (bytes > maxBytes)
    throw std::runtime_error(named(what, path) + " has " + std::to_string(bytes) +
                             " bytes, more than the " + std::to_string(maxBytes) + " allowed");
  const WorkPhase phase("reading " + named(what, path) + " (" + std::to_string(bytes) + " bytes)");
  std::string text(static_cast<size_t>(bytes), '\0');
  if (!file.read(text.data(), static_cast<std::streamsize>(bytes)))
    throw std::runtime_error("cannot read " + named(what, path));
  return text;
}

}  // namespace rtu
