#pragma once
// Seed 001's 6-cycle divider, Altera's altfp_div as R1 generated it (COMMON/altfp_div/altfp_div.v,
// `altfp_dia_altfp_div_pst_6dj`, with its ROM altfp_dia.hex), as a function of its inputs: the
// netlist's datapath read from its lpm_mult, lpm_add_sub and lpm_compare instances and their
// wiring (no code taken from it; R1 has no licence). Its pipeline registers only delay values, so
// the result is this function of the inputs six cycles before.
//
// The mantissa, for normal a / b with 23-bit fractions ma, mb (docs/triangles.md, "Arithmetic"):
//   e0 = the ROM at mb's top 9 bits: floor(2^19 / (513 + index)) - 512 (every one of the file's
//        512 entries), E0 = 512 + e0, a 10-bit reciprocal seed of 1.mb;
//   A  = 1.ma as 24 bits, or 2 x 1.ma as 25 bits when ma < mb (the exponent's bias 126, else
//        127); B = 1.mb as 24 bits;
//   a1 = A E0, b1 = B E0; e1 = the complement of b1's top 17 bits (about 2 - b1, the seed's
//        Newton step);
//   qj = bits 32..16 of (a1's top 17 bits) e1;
//   r  = bits 35..19 of (a1 2^15 - b1 qj) mod 2^50 (the remainder); q1 = r e1;
//   mantissa = (qj 2^8 + q1's bits 32..22 + cin) mod 2^23, cin = q1[21] & (q1[22] | q1[20..16]):
//        round to nearest even on the estimate's bits, not on the exact quotient, so the result
//        is sometimes one ulp small (never large).
// Exponent ea - eb + bias: 255 or more gives infinity, 0 or less zero (no denormals). Special
// cases as its flags: NaN (a or b NaN, inf / inf, 0 / 0; mantissa 0x400000), infinity (a infinite,
// or b zero with a finite: division_by_zero), zero (a zero, b infinite). Tested against R1's
// netlist simulated with Altera's models: tests/test_altfp_div.cpp.

#include <cstdint>

namespace rtu {

struct AltfpQuotient {
  uint32_t bits = 0;  // the result, binary32
  bool divisionByZero = false;
};

// The ROM altfp_dia.hex: entry i is floor(2^19 / (513 + i)) - 512.
inline uint32_t altfpReciprocalSeed(uint32_t index) { return (1u << 19) / (513u + index) - 512u; }

// The 23-bit result fraction of 1.ma / 1.mb (aSmaller: ma < mb, the quotient below 1).
inline uint32_t altfpFraction(uint32_t ma, uint32_t mb, bool aSmaller) {
  const uint64_t e0 = 512u + altfpReciprocalSeed(mb >> 14);
  const uint64_t a = aSmaller ? (uint64_t{1} << 24) | (uint64_t{ma} << 1)
                              : (uint64_t{1} << 23) | ma;
  const uint64_t b = (uint64_t{1} << 23) | mb;
  const uint64_t a1 = a * e0, b1 = b * e0;
  const uint64_t e1 = ~(b1 >> 17) & 0x1ffffu;
  const uint64_t qj = (((a1 >> 18) * e1) >> 16) & 0x1ffffu;
  const uint64_t mask50 = (uint64_t{1} << 50) - 1;
  const uint64_t remainder = ((a1 << 15) - ((b1 * qj) & mask50)) & mask50;
  const uint64_t q1 = ((remainder >> 19) & 0x1ffffu) * e1;
  const uint64_t guard = (q1 >> 22) & 1u, round = (q1 >> 21) & 1u;
  const uint64_t sticky = ((q1 >> 16) & 0x1fu) != 0;
  const uint64_t cin = round & (guard | sticky);
  return static_cast<uint32_t>(((qj << 8) + ((q1 >> 22) & 0x7ffu) + cin) & 0x7fffffu);
}

// a / b as binary32 bit patterns, with the division_by_zero flag.
inline AltfpQuotient altfpDivide(uint32_t a, uint32_t b) {
  const uint32_t sign = (a ^ b) & 0x80000000u;
  const uint32_t ea = (a >> 23) & 0xffu, eb = (b >> 23) & 0xffu;
  const uint32_t ma = a & 0x7fffffu, mb = b & 0x7fffffu;
  const bool aInf = ea == 0xff && ma == 0, bInf = eb == 0xff && mb == 0;
  const bool aNan = ea == 0xff && ma != 0, bNan = eb == 0xff && mb != 0;
  const uint32_t infinity = sign | 0x7f800000u, zero = sign;
  if (aNan || bNan || (aInf && bInf) || (ea == 0 && eb == 0)) return {sign | 0x7fc00000u, false};
  if (aInf) return {infinity, false};
  if (eb == 0) return {infinity, true};  // division_by_zero: b zero (or denormal), a finite
  if (ea == 0 || bInf) return {zero, false};
  const bool aSmaller = ma < mb;
  const int e = static_cast<int>(ea) - static_cast<int>(eb) + (aSmaller ? 126 : 127);
  if (e >= 0xff) return {infinity, false};
  if (e <= 0) return {zero, false};
  return {sign | static_cast<uint32_t>(e) << 23 | altfpFraction(ma, mb, aSmaller), false};
}

}  // namespace rtu
