#pragma once
// An architecture's hardware as its configuration sizes it (issue 30 §2; docs/comparison.md,
// "Resources"): its on-chip memory arrays (stacks, FIFOs, caches, ray stores, result buffers, a
// scene held on chip) and its arithmetic units by kind, number format and width, with the FPGA
// figures a user compares by: 18 Kbit block RAMs, DSP48E slices and, optionally, the LUTs of the
// arithmetic. Each kind sizes its own core (kinds/<kind>/<kind>_resources.h), the RTU its caches
// and buffers (sim/rtu_resources.h), the ray pipe its units (raypipe/raypipe_resources.h).

#include <cstdint>
#include <string>
#include <vector>

namespace rtu {

enum class ArithmeticKind { Adder, Multiplier, Divider, Comparator };
enum class NumberKind { Fixed, Float };

// `count` units of one kind: `width` bits an operand (32 for binary32), `otherWidth` the second
// operand's where it differs (a fixed multiplier's; 0: the same).
struct ArithmeticUnits {
  std::string where;
  ArithmeticKind kind = ArithmeticKind::Adder;
  NumberKind number = NumberKind::Fixed;
  int width = 32;
  int64_t count = 1;
  int otherWidth = 0;
};

// `count` arrays of `depth` words of `width` bits.
struct MemoryArray {
  std::string name;
  int64_t depth = 0;
  int width = 0;
  int64_t count = 1;
  int64_t bits() const { return depth * width * count; }
};

// An array of at most this many words is registers or LUT RAM, as synthesis maps shallow arrays,
// not block RAM.
constexpr int64_t kDistributedDepth = 64;
constexpr int64_t kBlockRamBits = 18 * 1024;

struct ResourceEstimate {
  std::vector<MemoryArray> memories;
  std::vector<ArithmeticUnits> units;

  // `other`'s arrays and units `times` over (a core's for every core), each count multiplied.
  void add(const ResourceEstimate& other, int64_t times = 1);
  int64_t memoryBits() const;
  int64_t blockRamBits() const;  // the bits of the arrays in block RAM
  int64_t blockRams() const;     // 18 Kbit block RAM equivalents
  int64_t unitCount(ArithmeticKind kind) const;
  int64_t dsp48e() const;
  int64_t luts() const;  // the arithmetic's LUTs only (no control, muxes or memory)
};

// The 18 Kbit block RAMs of one array: none at kDistributedDepth words or fewer, else the fewest
// over the RAMB18's aspect ratios (16K x 1, 8K x 2, 4K x 4, 2K x 9, 1K x 18, 512 x 36), tiled.
int64_t blockRamsOf(int64_t depth, int width);
// DSP48E slices of one unit: a multiplier tiles its operands over the slice's 25 x 18 signed
// multiplier (a binary32 one its 24-bit significands: 2); every other unit is logic (0).
int64_t dsp48eOf(const ArithmeticUnits& unit);
// LUT6s of one unit's logic: a fixed adder or comparator one a bit (the carry chain), a fixed
// divider width x width (a pipelined array), a fixed multiplier none (in DSPs); binary32 adder
// 390, multiplier 80, divider 800, comparator 40 (the order of Xilinx's Floating-Point cores).
int64_t lutsOf(const ArithmeticUnits& unit);

const char* toString(ArithmeticKind kind);
const char* toString(NumberKind number);

// What a core kind brings: its traversal core and, for a kind with one, its ray/triangle unit
// (shared by RtuConfig::triangleSharedBy cores).
struct CoreResources {
  ResourceEstimate core;
  ResourceEstimate triangleUnit;
};

}  // namespace rtu
