#include "explore/sweep_workers.h"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <map>
#include <stdexcept>
#include <thread>

#include "base/isolated_process.h"

namespace rtu {
namespace {

std::string clockText(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  return text;
}

struct Worker {
  pid_t pid;
  int fd;
  size_t row;
  std::string output;
  size_t heardUpTo = 0;  // output handed to `heard` so far
};

void writeAll(int fd, const std::string& text) {
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    written += static_cast<size_t>(n);
  }
}

Worker startWorker(size_t row, const std::function<void(size_t, const WorkerSay&)>& work) {
  int pipeFds[2];
  if (::pipe(pipeFds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::cout.flush();
  std::cerr.flush();
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    dieWithParent(parent);  // no orphan runs on when the sweep is killed
    ::close(pipeFds[0]);
    work(row, [fd = pipeFds[1]](const std::string& text) { writeAll(fd, text); });
    ::_exit(0);  // no destructors or atexit handlers of the parent's objects in the child
  }
  ::close(pipeFds[1]);
  return {pid, pipeFds[0], row, {}};
}

// Hands the complete lines the worker said since the last call to `heard`.
void passLines(Worker& worker, const std::function<void(size_t, const std::string&)>& heard) {
  if (!heard) return;
  size_t end;
  while ((end = worker.output.find('\n', worker.heardUpTo)) != std::string::npos) {
    heard(worker.row, worker.output.substr(worker.heardUpTo, end - worker.heardUpTo));
    worker.heardUpTo = end + 1;
  }
}

WorkerOutcome finishWorker(Worker& worker) {
  ::close(worker.fd);
  int status = 0;
  while (::waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
  }
  WorkerOutcome outcome;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !worker.output.empty()) {
    outcome.answered = true;
    outcome.line = worker.output;
  } else if (WIFSIGNALED(status)) {
    outcome.failure = "worker killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                      strsignal(WTERMSIG(status)) + ")";
  } else {
    outcome.failure =
        "worker exited with status " + std::to_string(WEXITSTATUS(status)) + " without a result";
  }
  return outcome;
}

}  // namespace

Progress::Progress(std::string label, size_t total, std::string unit)
    : label_(std::move(label)),
      total_(total),
      unit_(std::move(unit)),
      terminal_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()),
      lastPrinted_(start_) {}

std::string progressText(const std::string& label, size_t done, size_t total,
                         const std::string& unit, size_t failed, double elapsedSeconds,
                         double workDone) {
  std::string text = label + " " + std::to_string(done) + "/" + std::to_string(total) + " " + unit;
  if (failed > 0) text += ", " + std::to_string(failed) + " failed";
  text += ", " + clockText(elapsedSeconds) + " elapsed";
  if (done < total && workDone > 0 && workDone < 1)
    text += ", ETA " + clockText(elapsedSeconds / workDone * (1 - workDone));
  return text;
}

std::string Progress::line(size_t done, size_t failed, double workDone) const {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return progressText(label_, done, total_, unit_, failed, elapsed, workDone);
}

void Progress::update(size_t done, size_t failed) {
  update(done, failed, total_ == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total_));
}

void Progress::update(size_t done, size_t failed, double workDone) {
  const auto now = std::chrono::steady_clock::now();
  const double sinceStart = std::chrono::duration<double>(now - start_).count();
  const double sincePrint = std::chrono::duration<double>(now - lastPrinted_).count();
  if (sinceStart < 2.0 || (!terminal_ && sincePrint < 5.0 && done < total_)) return;
  lastPrinted_ = now;
  printed_ = true;
  if (!terminal_) {
    std::cerr << line(done, failed, workDone) << "\n";
    return;
  }
  constexpr size_t kWidth = 30;
  const size_t filled = total_ == 0 ? kWidth : done * kWidth / total_;
  std::cerr << "\r[" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] "
            << line(done, failed, workDone) << "\033[K" << std::flush;
}

void Progress::finish() {
  if (printed_ && terminal_) std::cerr << "\n";
}

void runInWorkers(const std::vector<size_t>& rows, int workers,
                  const std::function<std::string(size_t)>& work,
                  const std::function<void(size_t, const WorkerOutcome&)>& done) {
  runInWorkers(
      rows, workers, [&work](size_t row, const WorkerSay& say) { say(work(row)); }, {}, done);
}

namespace {

void runNextInWorkers(const NextRow& nextRow, int workers,
                      const std::function<void(size_t, const WorkerSay&)>& work,
                      const std::function<void(size_t, const std::string&)>& heard,
                      const std::function<void(size_t, const WorkerOutcome&)>& done) {
  std::vector<Worker> running;
  bool more = true;
  size_t row = 0;
  while (more || !running.empty()) {
    while (more && static_cast<int>(running.size()) < std::max(1, workers) && (more = nextRow(row)))
      running.push_back(startWorker(row, work));
    if (running.empty()) break;
    std::vector<pollfd> fds;
    for (const Worker& worker : running) fds.push_back({worker.fd, POLLIN, 0});
    if (::poll(fds.data(), fds.size(), 1000) < 0 && errno != EINTR)
      throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    for (size_t i = fds.size(); i-- > 0;) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      char buffer[65536];
      const ssize_t n = ::read(running[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        running[i].output.append(buffer, static_cast<size_t>(n));
        passLines(running[i], heard);
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      Worker finished = running[i];
      running.erase(running.begin() + static_cast<long>(i));
      done(finished.row, finishWorker(finished));
    }
  }
}

}  // namespace

void runInWorkers(const std::vector<size_t>& rows, int workers,
                  const std::function<void(size_t, const WorkerSay&)>& work,
                  const std::function<void(size_t, const std::string&)>& heard,
                  const std::function<void(size_t, const WorkerOutcome&)>& done) {
  size_t next = 0;
  const NextRow nextRow = [&](size_t& row) {
    if (next == rows.size()) return false;
    row = rows[next++];
    return true;
  };
  runNextInWorkers(nextRow, workers, work, heard, done);
}

void runInWorkers(const NextRow& nextRow, int workers,
                  const std::function<std::string(size_t)>& work,
                  const std::function<void(size_t, const WorkerOutcome&)>& done) {
  runNextInWorkers(
      nextRow, workers, [&work](size_t row, const WorkerSay& say) { say(work(row)); }, {}, done);
}

int defaultWorkerCount() {
  const unsigned cores = std::thread::hardware_concurrency();
  return cores == 0 ? 1 : static_cast<int>(cores);
}

}  // namespace rtu
