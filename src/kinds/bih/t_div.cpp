#include "kinds/bih/t_div.h"

#include <cstdlib>

namespace rtu {
namespace {

TDivResult exactDivide(int64_t a, int64_t b, int w) {
  const uint64_t magnitudeA = std::llabs(a), magnitudeB = std::llabs(b);
  TDivResult out;
  out.err = (a < 0) != (b < 0) || magnitudeA >= magnitudeB;
  if (!out.err) out.q = (magnitudeA << (w - 2)) / magnitudeB;
  return out;
}

// |x| of x's w-bit pattern in w - 1 bits, and x's sign bit.
uint64_t magnitude(int64_t x, int w, uint64_t low) {
  const bool negative = (static_cast<uint64_t>(x) >> (w - 1)) & 1;
  return (negative ? ~static_cast<uint64_t>(x) + 1 : static_cast<uint64_t>(x)) & low;
}

TDivResult literalDivide(int64_t a, int64_t b, int w) {
  const uint64_t low = (uint64_t(1) << (w - 1)) - 1;  // the (w-1)-bit window
  const uint64_t divisor = magnitude(b, w, low);
  uint64_t qn = magnitude(a, w, low) << (w - 2);
  TDivResult out;
  const bool signA = (static_cast<uint64_t>(a) >> (w - 1)) & 1;
  const bool signB = (static_cast<uint64_t>(b) >> (w - 1)) & 1;
  out.err = signA != signB || (qn >> (w - 2)) >= divisor;
  for (int i = w - 2; i >= 0; --i) {
    const bool subtract = i == w - 2 || ((qn >> (i + w - 1)) & 1) == 0;
    const uint64_t window = (qn >> i) & low;
    const uint64_t next = (subtract ? window - divisor : window + divisor) & low;
    qn = (qn & ~(low << i)) | next << i;
  }
  out.q = ~(qn >> (w - 2)) & low;
  return out;
}

}  // namespace

TDivResult tDivide(int64_t a, int64_t b, int w, TDivModel model) {
  return model == TDivModel::Exact ? exactDivide(a, b, w) : literalDivide(a, b, w);
}

}  // namespace rtu
