#pragma once
// The per-cycle reference of seed 001's ray pipe (issue 29 §3): its two FIFOs, read from R1.
//
// RegFifo: R1 COMMON/library.sv `fifo` (register FIFO). Its count is registered: an item written
//   in cycle t is at the head from cycle t + 1; `empty`, `full` and num_left_in_fifo are the
//   counts at the start of the cycle (a read in the cycle frees a slot only from the next one);
//   a write while full is dropped by the RTL (write_valid = we & ~full), here a logic_error.
// ShowAheadFifo: the Altera scfifo the BRAM FIFOs are (COMMON/altbram_fifo/*.v: lpm_showahead
//   ON, add_ram_output_register OFF, use_eab ON, Cyclone IV E: altera_mf.v's "showahead_area"
//   path). An item written in cycle t is shown at the head (empty low) from cycle t + 2 at the
//   earliest: the write lands at the edge ending t, the head register and empty flag follow at
//   the edge ending t + 1; after a read in cycle r, the next item is shown in r + 1 if it was
//   written by r - 1. usedw and full count every written item from the cycle after its write.
//
// Both stage reads and writes during a cycle and apply them at tick(), so every query in a cycle
// sees the state at its start, as the RTL's combinational logic sees the flip-flops.

#include <algorithm>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>

namespace rtu {
namespace raypipe_ref {

// What every FIFO reports: its name, depth and highest occupancy.
class FifoStats {
 public:
  FifoStats(std::string name, int depth) : name_(std::move(name)), depth_(depth) {}
  const std::string& name() const { return name_; }
  int depth() const { return depth_; }
  int peak() const { return peak_; }

 protected:
  void notePeak(int size) { peak_ = std::max(peak_, size); }
  [[noreturn]] void overflow() const {
    throw std::logic_error("raypipe reference: write to the full FIFO " + name_);
  }
  std::string name_;
  int depth_;
  int peak_ = 0;
};

template <class T>
class RegFifo : public FifoStats {
 public:
  RegFifo(std::string name, int depth) : FifoStats(std::move(name), depth) {}
  int size() const { return static_cast<int>(items_.size()); }
  bool empty() const { return items_.empty(); }
  bool full() const { return size() >= depth_; }
  int numLeft() const { return depth_ - size(); }
  bool valid(int64_t) const { return !empty(); }  // the head shown this cycle
  const T& front() const { return items_.front(); }
  // Holds `item` at the cycle's start (R1's exists_in_fifo).
  bool contains(const T& item) const {
    return std::find(items_.begin(), items_.end(), item) != items_.end();
  }
  void pop() {  // re & ~empty
    if (!empty()) popped_ = true;
  }
  void push(int64_t, const T& item) {
    if (full() || pushed_) overflow();
    pushed_ = true;
    staged_ = item;
  }
  void tick(int64_t) {
    if (popped_) items_.pop_front();
    if (pushed_) items_.push_back(staged_);
    popped_ = pushed_ = false;
    notePeak(size());
  }

 private:
  std::deque<T> items_;
  T staged_{};
  bool popped_ = false, pushed_ = false;
};

template <class T>
class ShowAheadFifo : public FifoStats {
 public:
  ShowAheadFifo(std::string name, int depth) : FifoStats(std::move(name), depth) {}
  int size() const { return static_cast<int>(items_.size()); }  // usedw with the full bit
  bool full() const { return size() >= depth_; }
  int numLeft() const { return depth_ - size(); }
  bool valid(int64_t now) const { return !items_.empty() && items_.front().written <= now - 2; }
  const T& front() const { return items_.front().item; }
  void pop() { popped_ = true; }  // only when valid
  void push(int64_t now, const T& item) {
    if (full() || pushed_) overflow();
    pushed_ = true;
    staged_ = Entry{item, now};
  }
  // An item written in cycle `written`, before the run's first cycle (the shader's ray ids).
  void preload(const T& item, int64_t written) {
    items_.push_back(Entry{item, written});
    notePeak(size());
  }
  void tick(int64_t) {
    if (popped_) items_.pop_front();
    if (pushed_) items_.push_back(staged_);
    popped_ = pushed_ = false;
    notePeak(size());
  }

 private:
  struct Entry {
    T item{};
    int64_t written = 0;
  };
  std::deque<Entry> items_;
  Entry staged_;
  bool popped_ = false, pushed_ = false;
};

}  // namespace raypipe_ref
}  // namespace rtu
