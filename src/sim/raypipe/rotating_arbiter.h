#pragma once
// R1's `arbitor` for the timed model: a VS_buf skid buffer per input, a rotating priority pointer,
// one grant a cycle into the output FIFO. Called only in a cycle some input offers or a VS_buf
// holds an item (otherwise the RTL's arbiter keeps its state: every stall register is low, since
// an input stalled in t is still valid in t + 1). Timing rules:
//   - an input's stall is its VS_buf's stall register (the downstream stall of the cycle before)
//     while it offers: it never depends on this cycle's choice;
//   - the pointer p advances every cycle the output FIFO is not full and any input is valid
//     (offered or held), whoever wins; the first valid input from p on is written;
//   - a valid input not written holds (VS_buf case 10) or keeps (11) its item; its stall register
//     goes high for the next cycle.

#include <array>
#include <cstdint>

#include "sim/raypipe/timed_queue.h"

namespace rtu {
namespace raypipe_timed {

template <class T, int N>
class RotatingArbiter {
 public:
  RotatingArbiter(std::string name, int depth, int showDelay)
      : out_(std::move(name), depth, showDelay) {}

  bool holds() const {
    for (const Input& in : inputs_)
      if (in.held) return true;
    return false;
  }
  // The cycle's choice over `offers` (null: no offer); returns the item written or null.
  const T* arbitrate(int64_t now, const std::array<const T*, N>& offers) {
    std::array<const T*, N> data{};
    bool any = false;
    for (int i = 0; i < N; ++i) {
      Input& in = inputs_[static_cast<size_t>(i)];
      offered_[static_cast<size_t>(i)] = offers[static_cast<size_t>(i)] != nullptr;
      stallUs_[static_cast<size_t>(i)] = in.stallReg && offered_[static_cast<size_t>(i)];
      data[static_cast<size_t>(i)] = in.held ? &in.item : offers[static_cast<size_t>(i)];
      any = any || data[static_cast<size_t>(i)] != nullptr;
    }
    stamp_ = now;
    int chosen = -1;
    if (!out_.full(now)) {
      for (int k = 0; k < N && chosen < 0; ++k) {
        const int i = (pointer_ + k) % N;
        if (data[static_cast<size_t>(i)]) chosen = i;
      }
      if (any) pointer_ = (pointer_ + 1) % N;
    }
    if (chosen >= 0) out_.push(now, *data[static_cast<size_t>(chosen)]);
    for (int i = 0; i < N; ++i) hold(i, data[static_cast<size_t>(i)] && i != chosen, offers);
    return chosen >= 0 ? &out_.back() : nullptr;
  }
  bool stallUs(int i, int64_t now) const {
    return stamp_ == now && stallUs_[static_cast<size_t>(i)];
  }
  bool accepted(int i, int64_t now) const {
    return stamp_ == now && offered_[static_cast<size_t>(i)] && !stallUs_[static_cast<size_t>(i)];
  }
  TimedQueue<T>& out() { return out_; }
  const TimedQueue<T>& out() const { return out_; }

 private:
  struct Input {
    bool stallReg = false, held = false;
    T item{};
  };
  // VS_buf's edge: stall_reg := stall_ds; 10 holds the upstream item, 11 keeps, 0x empties.
  void hold(int i, bool stallDs, const std::array<const T*, N>& offers) {
    Input& in = inputs_[static_cast<size_t>(i)];
    if (stallDs && !in.stallReg) {
      in.held = offers[static_cast<size_t>(i)] != nullptr;
      if (in.held) in.item = *offers[static_cast<size_t>(i)];
    } else if (!stallDs) {
      in.held = false;
    }
    in.stallReg = stallDs;
  }
  std::array<Input, N> inputs_{};
  std::array<bool, N> offered_{}, stallUs_{};
  TimedQueue<T> out_;
  int pointer_ = 0;
  int64_t stamp_ = INT64_MIN;
};

}  // namespace raypipe_timed
}  // namespace rtu
