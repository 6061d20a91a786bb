#pragma once
// The per-cycle reference of seed 001's ray pipe: R1 COMMON/library.sv `pipe_valid_stall`, the
// fixed-latency pipe that never stalls inside. An item accepted in cycle t (us_valid & ~us_stall)
// leaves in cycle t + DEPTH (valid_buf[0]) and must be taken then (into the FIFO behind it).
// one_cnt, registered, counts the items accepted before this cycle that have not left before it
// (the one leaving this cycle included); us_stall = ds_stall & (one_cnt >= num_left_in_fifo),
// combinational in the downstream stall and the FIFO's registered free slots.

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace rtu {
namespace raypipe_ref {

template <class T>
class PipeValidStall {
 public:
  explicit PipeValidStall(int depth) : depth_(depth), slots_(static_cast<size_t>(depth)) {}
  int depth() const { return depth_; }
  int oneCount() const { return oneCount_; }
  bool usStall(bool dsStall, int numLeft) const { return dsStall && oneCount_ >= numLeft; }
  bool outValid(int64_t now) const {
    const Slot& s = slots_[static_cast<size_t>(now % depth_)];
    return s.valid && s.exit == now;
  }
  const T& out(int64_t now) const { return slots_[static_cast<size_t>(now % depth_)].item; }
  bool busy() const { return oneCount_ > 0 || accepted_; }
  void accept(const T& item) {
    if (accepted_) throw std::logic_error("raypipe reference: two items into one pipe");
    accepted_ = true;
    staged_ = item;
  }
  void tick(int64_t now) {
    Slot& s = slots_[static_cast<size_t>(now % depth_)];
    const bool left = s.valid && s.exit == now;
    if (left) s.valid = false;
    if (accepted_) s = Slot{staged_, now + depth_, true};
    oneCount_ += (accepted_ ? 1 : 0) - (left ? 1 : 0);
    accepted_ = false;
  }

 private:
  struct Slot {
    T item{};
    int64_t exit = 0;
    bool valid = false;
  };
  int depth_;
  std::vector<Slot> slots_;
  int oneCount_ = 0;
  bool accepted_ = false;
  T staged_{};
};

}  // namespace raypipe_ref
}  // namespace rtu
