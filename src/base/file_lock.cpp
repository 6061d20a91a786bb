#include "base/file_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace rtu {
namespace {

std::string holder(int fd) {
  char text[256] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string said(text, n > 0 ? static_cast<size_t>(n) : 0);
  while (!said.empty() && (said.back() == '\n' || said.back() == '\0')) said.pop_back();
  return said.empty() ? "another process" : said;
}

std::string self() {
  char host[256] = {};
  ::gethostname(host, sizeof host - 1);
  return "process " + std::to_string(::getpid()) + " on host " + host + "\n";
}

}  // namespace

FileLock::FileLock(const std::string& path, const std::string& what)
    : fd_(::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666)) {
  if (fd_ < 0)
    throw std::runtime_error("cannot create the lock file '" + path + "': " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string message =
        error == EWOULDBLOCK ? what + " is in use by " + holder(fd_) + " (lock file '" + path + "')"
                             : "cannot lock '" + path + "': " + std::strerror(error);
    ::close(fd_);
    throw std::runtime_error(message);
  }
  const std::string me = self();
  if (::ftruncate(fd_, 0) != 0 ||
      ::pwrite(fd_, me.data(), me.size(), 0) != static_cast<ssize_t>(me.size())) {
    const int error = errno;
    ::close(fd_);
    throw std::runtime_error("cannot write the lock file '" + path + "': " + std::strerror(error));
  }
}

FileLock::~FileLock() { ::close(fd_); }

}  // namespace rtu
