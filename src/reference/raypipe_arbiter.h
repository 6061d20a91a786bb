#pragma once
// The per-cycle reference of seed 001's ray pipe: R1 COMMON/library.sv `arbitor` and, with more
// than one output, `general_arbitor` (raypipe_2trav.sv's tarb, 5 -> 2).
//
// RotatingArbiter: a VS_buf per input; each output in turn (0 first), when its FIFO is not full,
//   takes the first offering input in the order p, p+1, ... that no earlier output took, one a
//   cycle; every other offering input is stalled. The priority pointer p (rrptr_arr[0]) advances by
//   one every cycle some input is taken, whoever wins (with one output: every cycle the output FIFO
//   is not full and any VS_buf offers an item). The output FIFOs are 512-deep show-ahead BRAM FIFOs
//   for the tarb_t and leaf_info_t widths (tarb, larb), else a 2-entry register FIFO (the
//   shader's). N is the most inputs; `inputs` of them are used.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/raypipe_vs_buf.h"

namespace rtu {
namespace raypipe_ref {

template <class T, int N, class Fifo>
class RotatingArbiter {
 public:
  RotatingArbiter(const std::string& name, int depth, int inputs = N, int outputs = 1)
      : inputs_(inputs) {
    for (int o = 0; o < outputs; ++o)
      fifos_.emplace_back(o == 0 ? name : name + "_" + std::to_string(o), depth);
  }
  int outputs() const { return static_cast<int>(fifos_.size()); }

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

  // The choice of the cycle: writes each output's winner into its FIFO.
  void arbitrate(int64_t now) {
    taken_ = {};
    chosen_.fill(-1);
    bool any = false;
    for (int o = 0; o < outputs(); ++o) {
      if (fifos_[static_cast<size_t>(o)].full()) continue;
      for (int k = 0; k < inputs_; ++k) {
        const int i = (pointer_ + k) % inputs_;
        if (!validDs(i) || taken_[static_cast<size_t>(i)]) continue;
        taken_[static_cast<size_t>(i)] = any = true;
        chosen_[static_cast<size_t>(o)] = i;
        fifos_[static_cast<size_t>(o)].push(now, data(i));
        break;
      }
    }
    if (any) pointer_ = (pointer_ + 1) % inputs_;
  }
  // The item written into output o's FIFO this cycle (after arbitrate, before tick), or null.
  const T* granted(int o = 0) const {
    const int i = chosen_[static_cast<size_t>(o)];
    return i >= 0 ? &data(i) : nullptr;
  }
  Fifo& out(int o = 0) { return fifos_[static_cast<size_t>(o)]; }
  const Fifo& out(int o = 0) const { return fifos_[static_cast<size_t>(o)]; }

  void tick(int64_t now) {
    for (int i = 0; i < inputs_; ++i) {
      const size_t s = static_cast<size_t>(i);
      vs_[s].tick(us_[s] != nullptr, us_[s], validDs(i) && !taken_[s]);
      us_[s] = nullptr;
    }
    taken_ = {};
    chosen_.fill(-1);
    for (Fifo& f : fifos_) f.tick(now);
  }

 private:
  static constexpr int kMaxOutputs = 2;  // tarb with two traversal units
  bool validDs(int i) const {
    return vs_[static_cast<size_t>(i)].validDs(us_[static_cast<size_t>(i)] != nullptr);
  }
  const T& data(int i) const {
    return vs_[static_cast<size_t>(i)].dataDs(us_[static_cast<size_t>(i)]);
  }
  int inputs_;
  std::array<VsBuf<T>, N> vs_{};
  std::array<const T*, N> us_{};
  std::array<T, N> items_{};
  std::vector<Fifo> fifos_;
  int pointer_ = 0;
  std::array<bool, N> taken_{};
  std::array<int, kMaxOutputs> chosen_{-1, -1};
};

}  // namespace raypipe_ref
}  // namespace rtu
