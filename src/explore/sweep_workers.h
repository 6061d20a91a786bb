#pragma once
// Rows of an exploration run (or ranges of an animation's frames) in parallel worker processes,
// with a progress line.
//
// Each row runs in a process forked for it, so rows share what the parent built before (the
// scenes) without copying, a row that crashes or is killed takes only itself down, and every
// row gets a fresh SystemC kernel. The parent hands each finished row's line to `done` as it
// arrives, so callers can write rows as they finish.

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rtu {

// "sweep 12/40 rows, 1 failed, 0:00:30 elapsed, ETA 0:00:42" on standard error: a bar redrawn in
// place on a terminal, plain lines at most every five seconds otherwise; silent for runs shorter
// than two seconds.
class Progress {
 public:
  Progress(std::string label, size_t total, std::string unit = "rows");
  // `workDone`: the share of the whole work done, 0 .. 1, where items differ in size (rows in
  // rays); the ETA follows it. Without it every item counts alike.
  void update(size_t done, size_t failed, double workDone);
  void update(size_t done, size_t failed);
  void finish();

 private:
  std::string line(size_t done, size_t failed, double workDone) const;

  std::string label_;
  size_t total_;
  std::string unit_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_, lastPrinted_;
  bool printed_ = false;
};

// Progress's line: "sweep 12/40 rows, 1 failed, 0:00:30 elapsed, ETA 0:00:42", the ETA being the
// time the work still to do (1 - workDone) takes at the rate of the work done so far.
std::string progressText(const std::string& label, size_t done, size_t total,
                         const std::string& unit, size_t failed, double elapsedSeconds,
                         double workDone);

// Progress of one simulation (rays received by the host), for simulateRtu's callback.
class RunProgressLine {
 public:
  RunProgressLine(std::string label, std::string unit)
      : label_(std::move(label)), unit_(std::move(unit)) {}
  ~RunProgressLine() {
    if (progress_) progress_->finish();
  }
  std::function<void(size_t, size_t)> callback() {
    return [this](size_t done, size_t total) {
      if (!progress_) progress_ = std::make_unique<Progress>(label_, total, unit_);
      progress_->update(done, 0);
    };
  }

 private:
  std::string label_, unit_;
  std::unique_ptr<Progress> progress_;
};

struct WorkerOutcome {
  bool answered = false;  // false: the worker died (signal, crash) before answering
  std::string line;       // its answer
  std::string failure;    // why it did not answer
};

// Runs `work(row)` for each row in up to `workers` worker processes at once and calls
// `done(row, outcome)` in the parent as each finishes. `work` returns one line (must not throw).
void runInWorkers(const std::vector<size_t>& rows, int workers,
                  const std::function<std::string(size_t)>& work,
                  const std::function<void(size_t, const WorkerOutcome&)>& done);

// For work that answers as it goes: `work(row, say)` hands the parent text at once with `say`,
// and the parent calls `heard(row, line)` for each line ('\n' ended) as it arrives, then
// `done(row, outcome)` with all the text the worker said. `work` must not throw.
using WorkerSay = std::function<void(const std::string&)>;
void runInWorkers(const std::vector<size_t>& rows, int workers,
                  const std::function<void(size_t, const WorkerSay&)>& work,
                  const std::function<void(size_t, const std::string&)>& heard,
                  const std::function<void(size_t, const WorkerOutcome&)>& done);

// The rows taken one at a time as workers free up (a sweep's rows are not held together):
// `nextRow(row)` sets the next row, false when there is none.
using NextRow = std::function<bool(size_t&)>;
void runInWorkers(const NextRow& nextRow, int workers,
                  const std::function<std::string(size_t)>& work,
                  const std::function<void(size_t, const WorkerOutcome&)>& done);

int defaultWorkerCount();

}  // namespace rtu
