#include "base/isolated_process.h"

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/asan_interface.h>
#endif

namespace rtu {
namespace {

using Clock = std::chrono::steady_clock;

// The child's exit status when an allocation fails (from its new handler).
constexpr int kOutOfMemoryExit = 86;
// First byte of the child's answer: what follows is the result or an error message.
constexpr char kAnswered = '+';
constexpr char kFailed = '!';

void writeAll(int fd, const char* data, size_t size) {
  size_t written = 0;
  while (written < size) {
    const ssize_t n = ::write(fd, data + written, size - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    written += static_cast<size_t>(n);
  }
}

// The address space the process already uses: the child starts with the parent's, and the
// memory limit is on what it adds.
uint64_t currentAddressSpaceBytes() {
  std::ifstream statm("/proc/self/statm");
  uint64_t pages = 0;
  statm >> pages;
  return pages * static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
}

void setLimit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit limit{soft, hard};
  ::setrlimit(resource, &limit);  // best effort: a lower hard limit already in place still holds
}

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer's own report of a failed allocation needs address space of its own: with only
// the limit's bytes left it died half-way ("Failed to mmap", exit status 1) before the report
// callback could name the cause. Its redzones and quarantine inflate the work's usage anyway.
constexpr uint64_t kSanitizerHeadroomBytes = uint64_t{256} << 20;
#else
constexpr uint64_t kSanitizerHeadroomBytes = 0;
#endif

void limitChild(const ProcessLimits& limits) {
  setLimit(RLIMIT_AS, currentAddressSpaceBytes() + limits.memoryBytes + kSanitizerHeadroomBytes,
           RLIM_INFINITY);
  const auto cpuSeconds = static_cast<rlim_t>(std::ceil(limits.seconds));
  setLimit(RLIMIT_CPU, cpuSeconds, cpuSeconds + 1);  // SIGXCPU, then SIGKILL a second later
  setLimit(RLIMIT_CORE, 0, 0);  // a crash on a malformed input is expected: no core files
}

// The parent's handlers of fatal signals (a test framework's, say) would report the child's
// crash as the parent's own; the child dies of the signal so that the parent can name it.
void restoreFatalSignals() {
  for (int signal : {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL, SIGTRAP, SIGSYS, SIGXCPU})
    std::signal(signal, SIG_DFL);
}

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer reports a failed allocation and exits instead of calling the new handler:
// recognising its report keeps the sanitizer build's message that of the release build.
void onSanitizerReport(const char* report) {
  if (std::strstr(report, "out of memory") != nullptr ||
      std::strstr(report, "allocation-size-too-big") != nullptr)
    ::_exit(kOutOfMemoryExit);
}
#endif

[[noreturn]] void runChild(int fd, const std::function<std::string()>& work,
                           const ProcessLimits& limits) {
  restoreFatalSignals();
  limitChild(limits);
  std::set_new_handler([] { ::_exit(kOutOfMemoryExit); });
#if defined(__SANITIZE_ADDRESS__)
  __asan_set_error_report_callback(onSanitizerReport);
#endif
  char status = kAnswered;
  std::string answer;
  try {
    answer = work();
  } catch (const std::bad_alloc&) {
    ::_exit(kOutOfMemoryExit);
  } catch (const std::exception& exception) {
    status = kFailed;
    answer = exception.what();
  } catch (...) {
    status = kFailed;
    answer = "unknown error";
  }
  writeAll(fd, &status, 1);
  writeAll(fd, answer.data(), answer.size());
  ::_exit(0);  // no destructors or atexit handlers of the parent's objects in the child
}

struct ChildOutput {
  std::string bytes;
  bool timedOut = false;
  bool tooLong = false;
};

// Reads the child's answer until it closes the pipe, the deadline passes or the answer exceeds
// `maxBytes`; in the last two cases the child is killed.
ChildOutput readChild(int fd, pid_t pid, Clock::time_point deadline, uint64_t maxBytes) {
  ChildOutput output;
  char buffer[1 << 16];
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    pollfd request{fd, POLLIN, 0};
    const int ready = left.count() <= 0 ? 0 : ::poll(&request, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) output.timedOut = true;
    if (!output.timedOut) {
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return output;
      output.bytes.append(buffer, static_cast<size_t>(n));
      output.tooLong = output.bytes.size() > maxBytes + 1;
      if (!output.tooLong) continue;
    }
    ::kill(pid, SIGKILL);
    return output;
  }
}

int waitForChild(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

std::string secondsText(double seconds) {
  std::ostringstream text;
  text << seconds << " s";
  return text.str();
}

std::string mebibytesText(uint64_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

std::string signalName(int signal) {
  const char* abbreviation = ::sigabbrev_np(signal);
  return abbreviation != nullptr ? std::string("SIG") + abbreviation
                                 : "signal " + std::to_string(signal);
}

// The answer of a child that exited with `status` after writing `output`, or the error that
// says why there is none.
std::string interpret(const ChildOutput& output, int status, const ProcessLimits& limits) {
  if (output.timedOut)
    throw IsolatedProcessError("did not finish within " + secondsText(limits.seconds));
  if (output.tooLong)
    throw IsolatedProcessError("answered more than " + mebibytesText(limits.memoryBytes));
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    if (signal == SIGXCPU || signal == SIGKILL)  // SIGKILL: the hard CPU limit, or the kernel
      throw IsolatedProcessError("did not finish within " + secondsText(limits.seconds) +
                                 " of processor time or was killed for lack of memory (" +
                                 signalName(signal) + ")");
    throw IsolatedProcessError("crashed (" + signalName(signal) + ")");
  }
  if (WEXITSTATUS(status) == kOutOfMemoryExit)
    throw IsolatedProcessError("needed more than " + mebibytesText(limits.memoryBytes) +
                               " of memory");
  if (WEXITSTATUS(status) != 0)
    throw IsolatedProcessError("exited with status " + std::to_string(WEXITSTATUS(status)));
  if (output.bytes.empty()) throw IsolatedProcessError("exited without an answer");
  if (output.bytes[0] != kAnswered) throw std::runtime_error(output.bytes.substr(1));
  return output.bytes.substr(1);
}

}  // namespace

void dieWithParent(int parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  // The parent may have died between the fork and the prctl: the child was then re-parented
  // and no signal will come.
  if (::getppid() != parent) ::_exit(1);
}

std::string runIsolated(const std::function<std::string()>& work, const ProcessLimits& limits) {
  int pipeFds[2];
  if (::pipe(pipeFds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::cout.flush();  // or the child's copy of the buffers could be written twice
  std::cerr.flush();
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(limits.seconds));
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int error = errno;
    ::close(pipeFds[0]);
    ::close(pipeFds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(error));
  }
  if (pid == 0) {
    dieWithParent(parent);  // a killed parent (Ctrl-C) takes the child with it
    ::close(pipeFds[0]);
    runChild(pipeFds[1], work, limits);
  }
  ::close(pipeFds[1]);
  const ChildOutput output = readChild(pipeFds[0], pid, deadline, limits.memoryBytes);
  ::close(pipeFds[0]);
  return interpret(output, waitForChild(pid), limits);
}

}  // namespace rtu
