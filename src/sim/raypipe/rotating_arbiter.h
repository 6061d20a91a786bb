#pragma once
// R1's `arbitor` and `general_arbitor` (COMMON/library.sv) for the timed model: a VS_buf skid
// buffer per input, a rotating priority pointer, one grant a cycle into each output FIFO. With
// one output it is `arbitor`; with more (the tarb of raypipe_2trav.sv, 5 -> 2) `general_arbitor`.
// Called only in a cycle some input offers or a VS_buf holds an item (otherwise the RTL's arbiter
// keeps its state: every stall register is low, since an input stalled in t is still valid in
// t + 1). Timing rules:
//   - an input's stall is its VS_buf's stall register (the downstream stall of the cycle before)
//     while it offers: it never depends on this cycle's choice;
//   - output o in turn (0 first), when its FIFO is not full, takes the first valid input (offered
//     or held) from the pointer p on that no earlier output took;
//   - p advances every cycle some input is taken, whoever wins (with one output: every cycle the
//     output FIFO is not full and any input is valid);
//   - a valid input not taken holds (VS_buf case 10) or keeps (11) its item; its stall register
//     goes high for the next cycle.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/raypipe/timed_queue.h"

namespace rtu {
namespace raypipe_timed {

constexpr int kMaxArbiterInputs = 5;   // tarb with two traversal units
constexpr int kMaxArbiterOutputs = 2;  // tarb's outputs, one per traversal unit

template <class T>
class RotatingArbiter {
 public:
  using Offers = std::array<const T*, kMaxArbiterInputs>;
  using Grants = std::array<const T*, kMaxArbiterOutputs>;

  // `outputs` FIFOs named `name`, then `name`_1, ...
  RotatingArbiter(const std::string& name, int depth, int showDelay, int inputs, int outputs = 1)
      : inputs_(inputs) {
    for (int o = 0; o < outputs; ++o)
      out_.emplace_back(o == 0 ? name : name + "_" + std::to_string(o), depth, showDelay);
  }

  int inputs() const { return inputs_; }
  int outputs() const { return static_cast<int>(out_.size()); }
  bool holds() const {
    for (int i = 0; i < inputs_; ++i)
      if (in_[static_cast<size_t>(i)].held) return true;
    return false;
  }
  // The cycle's choice over `offers` (null: no offer); returns the item written into each output.
  Grants arbitrate(int64_t now, const Offers& offers) {
    Offers data{};
    for (size_t i = 0; i < static_cast<size_t>(inputs_); ++i) {
      offered_[i] = offers[i] != nullptr;
      stallUs_[i] = in_[i].stallReg && offered_[i];
      data[i] = in_[i].held ? &in_[i].item : offers[i];
    }
    stamp_ = now;
    std::array<bool, kMaxArbiterInputs> taken{};
    Grants grants{};
    bool any = false;
    for (size_t o = 0; o < out_.size(); ++o) {
      if (out_[o].full(now)) continue;
      for (int k = 0; k < inputs_; ++k) {
        const size_t i = static_cast<size_t>((pointer_ + k) % inputs_);
        if (!data[i] || taken[i]) continue;
        taken[i] = any = true;
        out_[o].push(now, *data[i]);
        grants[o] = &out_[o].back();
        break;
      }
    }
    if (any) pointer_ = (pointer_ + 1) % inputs_;
    for (size_t i = 0; i < static_cast<size_t>(inputs_); ++i)
      hold(i, data[i] && !taken[i], offers[i]);
    return grants;
  }
  bool stallUs(int i, int64_t now) const {
    return stamp_ == now && stallUs_[static_cast<size_t>(i)];
  }
  bool accepted(int i, int64_t now) const {
    return stamp_ == now && offered_[static_cast<size_t>(i)] && !stallUs_[static_cast<size_t>(i)];
  }
  TimedQueue<T>& out(int o = 0) { return out_[static_cast<size_t>(o)]; }
  const TimedQueue<T>& out(int o = 0) const { return out_[static_cast<size_t>(o)]; }

 private:
  struct Input {
    bool stallReg = false, held = false;
    T item{};
  };
  // VS_buf's edge: stall_reg := stall_ds; 10 holds the upstream item, 11 keeps, 0x empties.
  void hold(size_t i, bool stallDs, const T* offer) {
    Input& in = in_[i];
    if (stallDs && !in.stallReg) {
      in.held = offer != nullptr;
      if (in.held) in.item = *offer;
    } else if (!stallDs) {
      in.held = false;
    }
    in.stallReg = stallDs;
  }
  int inputs_;
  std::array<Input, kMaxArbiterInputs> in_{};
  std::array<bool, kMaxArbiterInputs> offered_{}, stallUs_{};
  std::vector<TimedQueue<T>> out_;
  int pointer_ = 0;
  int64_t stamp_ = INT64_MIN;
};

}  // namespace raypipe_timed
}  // namespace rtu
