#include "base/temporary_files.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>
#include <system_error>

namespace rtu {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPart = ".part-";
constexpr size_t kRandom = 6;  // mkostemps' X's

std::string hostName() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "host";
  std::string host(name);
  for (char& c : host)
    if (c == '/' || c == '-') c = '_';  // the name's fields are split at '-'
  return host.empty() ? "host" : host;
}

// ".frame.part-" for "frame.png".
std::string prefixOf(const fs::path& target) { return "." + target.stem().string() + kPart; }

// The pid in a temporary file's name of this host ("HOST-PID-XXXXXX" between the prefix and the
// extension), or 0 for any other name.
pid_t pidOf(const std::string& middle, const std::string& host) {
  const std::string ours = host + "-";
  if (middle.size() < ours.size() + 2 + kRandom || middle.compare(0, ours.size(), ours) != 0)
    return 0;
  const std::string pid = middle.substr(ours.size(), middle.size() - ours.size() - kRandom - 1);
  if (middle[middle.size() - kRandom - 1] != '-' || pid.empty() || pid.size() > 9 ||
      pid.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  return static_cast<pid_t>(std::stol(pid));
}

bool running(pid_t pid) { return ::kill(pid, 0) == 0 || errno != ESRCH; }

// The registered paths, read by the signal handler: each slot owns a copy made before it is
// published, so the handler reads only whole strings.
std::array<std::atomic<char*>, TemporaryRegistration::kMaxTemporaries> registered{};
std::once_flag handlerInstalled;

extern "C" void removeRegisteredAndEnd(int signal) {
  for (std::atomic<char*>& slot : registered)
    if (char* path = slot.load()) ::unlink(path);
  struct sigaction fallback {};
  fallback.sa_handler = SIG_DFL;
  ::sigemptyset(&fallback.sa_mask);
  ::sigaction(signal, &fallback, nullptr);
  ::raise(signal);
}

void installHandler() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction current {};
    if (::sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL ||
        (current.sa_flags & SA_SIGINFO))
      continue;  // ignored or handled by someone else: left as it is
    struct sigaction handler {};
    handler.sa_handler = removeRegisteredAndEnd;
    ::sigemptyset(&handler.sa_mask);
    ::sigaction(signal, &handler, nullptr);
  }
}

}  // namespace

std::string temporaryPattern(const fs::path& target) {
  const std::string name = prefixOf(target) + hostName() + "-" + std::to_string(::getpid()) + "-" +
                           std::string(kRandom, 'X') + target.extension().string();
  return (target.parent_path() / name).string();
}

void removeStaleTemporaries(const fs::path& target) {
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  const std::string prefix = prefixOf(target), extension = target.extension().string();
  const std::string host = hostName();
  std::error_code error;
  for (fs::directory_iterator entry(folder, error), end; !error && entry != end;
       entry.increment(error)) {
    const std::string name = entry->path().filename().string();
    if (name.size() < prefix.size() + extension.size() || name.compare(0, prefix.size(), prefix) ||
        name.compare(name.size() - extension.size(), extension.size(), extension))
      continue;
    const pid_t pid =
        pidOf(name.substr(prefix.size(), name.size() - prefix.size() - extension.size()), host);
    std::error_code ignored;
    if (pid > 0 && !running(pid) && entry->is_regular_file(ignored))
      fs::remove(entry->path(), ignored);
  }
}

TemporaryRegistration::TemporaryRegistration(const std::string& path) {
  std::call_once(handlerInstalled, installHandler);
  char* copy = ::strdup(path.c_str());
  for (int slot = 0; copy && slot < kMaxTemporaries; ++slot) {
    char* expected = nullptr;
    if (registered[static_cast<size_t>(slot)].compare_exchange_strong(expected, copy)) {
      slot_ = slot;
      return;
    }
  }
  std::free(copy);
}

// The handler may be reading the path in this thread: the signals wait while it is let go of.
TemporaryRegistration::~TemporaryRegistration() {
  if (slot_ < 0) return;
  sigset_t handled, before;
  ::sigemptyset(&handled);
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) ::sigaddset(&handled, signal);
  ::pthread_sigmask(SIG_BLOCK, &handled, &before);
  std::free(registered[static_cast<size_t>(slot_)].exchange(nullptr));
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
}

}  // namespace rtu
