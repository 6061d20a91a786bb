#pragma once
// x mod n for a divisor fixed at run time, such as a select counter's core count: a mask when n
// is a power of two (1, 4, 16, 64 cores...), where a 64-bit division would cost tens of cycles.

#include <cstdint>

namespace rtu {

class Modulo {
 public:
  explicit Modulo(uint64_t n) : n_(n), powerOfTwo_((n & (n - 1)) == 0) {}
  uint64_t of(uint64_t x) const { return powerOfTwo_ ? x & (n_ - 1) : x % n_; }

 private:
  uint64_t n_;
  bool powerOfTwo_;
};

}  // namespace rtu
