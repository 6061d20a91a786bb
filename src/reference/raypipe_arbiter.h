#pragma once
// The per-cycle reference of seed 001's ray pipe: R1 COMMON/library.sv `arbitor`.
//
// RotatingArbiter: `arbitor`: a VS_buf per input; priority pointer p (rrptr_arr[0]) advances by
//   one every cycle the output FIFO is not full and any VS_buf offers an item, whoever wins; the
//   first offering input in the order p, p+1, ... is written into the output FIFO, one a cycle;
//   every other offering input is stalled. The output FIFO is a 512-deep show-ahead BRAM FIFO for
//   the tarb_t and leaf_info_t widths (tarb, larb), else a 2-entry register FIFO (the shader's).

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "reference/raypipe_vs_buf.h"

namespace rtu {
namespace raypipe_ref {

template <class T, int N, class Fifo>
class RotatingArbiter {
 public:
  RotatingArbiter(std::string name, int depth) : fifo_(std::move(name), depth) {}

  // This cycle's upstream offers (null: not valid), copied: the upstream may pop its FIFO before
  // the arbiter's tick. Then stallUs(i) is the input's stall.
  void offer(int i, const T* item) {
    const size_t s = static_cast<size_t>(i);
    us_[s] = item ? &items_[s] : nullptr;
    if (item) items_[s] = *item;
  }
  bool stallUs(int i) const {
    return vs_[static_cast<size_t>(i)].stallUs(us_[static_cast<size_t>(i)] != nullptr);
  }
  // True when input i's offer is accepted into its VS_buf this cycle.
  bool accepted(int i) const { return us_[static_cast<size_t>(i)] != nullptr && !stallUs(i); }

  // The choice of the cycle: writes the winner into the output FIFO.
  void arbitrate(int64_t now) {
    chosen_ = -1;
    bool any = false;
    for (int k = 0; k < N; ++k) any = any || validDs(k);
    if (fifo_.full()) return;
    for (int k = 0; k < N && chosen_ < 0; ++k) {
      const int i = (pointer_ + k) % N;
      if (validDs(i)) chosen_ = i;
    }
    if (chosen_ >= 0) {
      fifo_.push(now, vs_[static_cast<size_t>(chosen_)].dataDs(us_[static_cast<size_t>(chosen_)]));
      ++grants_;
    }
    if (any) pointer_ = (pointer_ + 1) % N;
  }
  // The item written into the output FIFO this cycle (after arbitrate, before tick), or null.
  const T* granted() const {
    return chosen_ >= 0
               ? &vs_[static_cast<size_t>(chosen_)].dataDs(us_[static_cast<size_t>(chosen_)])
               : nullptr;
  }
  Fifo& out() { return fifo_; }
  const Fifo& out() const { return fifo_; }
  int64_t grants() const { return grants_; }

  void tick(int64_t now) {
    for (int i = 0; i < N; ++i) {
      const size_t s = static_cast<size_t>(i);
      vs_[s].tick(us_[s] != nullptr, us_[s], validDs(i) && i != chosen_);
      us_[s] = nullptr;
    }
    chosen_ = -1;
    fifo_.tick(now);
  }

 private:
  bool validDs(int i) const {
    return vs_[static_cast<size_t>(i)].validDs(us_[static_cast<size_t>(i)] != nullptr);
  }
  std::array<VsBuf<T>, N> vs_{};
  std::array<const T*, N> us_{};
  std::array<T, N> items_{};
  Fifo fifo_;
  int pointer_ = 0;
  int chosen_ = -1;
  int64_t grants_ = 0;
};

}  // namespace raypipe_ref
}  // namespace rtu
