#pragma once
// The per-cycle reference of seed 001's ray pipe: R1 COMMON/library.sv `VS_buf`, a one-entry skid
// buffer with a registered stall. stall_us = stall_reg & valid_us (so an arbiter's input stall
// never depends combinationally on anything downstream); valid_ds = tmp_valid | valid_us, the
// held item first. At the edge stall_reg := stall_ds and, by the RTL's case table on {stall_ds,
// stall_reg}: 10 holds the upstream item just accepted, 11 keeps the held one, 0x empties it. The
// case 01 with nothing held and an upstream item offered would pass one item twice (the
// downstream takes it while the upstream sees a stall); it cannot arise when the downstream
// stalls only valid items (the arbiter's stall_TMP = valid & ~choice) and is a logic_error here.

#include <stdexcept>

namespace rtu {
namespace raypipe_ref {

template <class T>
class VsBuf {
 public:
  bool validDs(bool validUs) const { return tmpValid_ || validUs; }
  const T& dataDs(const T* us) const { return tmpValid_ ? tmp_ : *us; }
  bool stallUs(bool validUs) const { return stallReg_ && validUs; }
  void tick(bool validUs, const T* us, bool stallDs) {
    if (stallDs && !stallReg_) {
      tmpValid_ = validUs;
      if (validUs) tmp_ = *us;
    } else if (!stallDs) {
      if (stallReg_ && !tmpValid_ && validUs)
        throw std::logic_error("raypipe reference: VS_buf passed an item twice");
      tmpValid_ = false;
    }
    stallReg_ = stallDs;
  }

 private:
  bool stallReg_ = false, tmpValid_ = false;
  T tmp_{};
};

}  // namespace raypipe_ref
}  // namespace rtu
