#include "rtu/resource_estimate.h"

#include <algorithm>
#include <array>
#include <utility>

namespace rtu {
namespace {

int64_t ceilDiv(int64_t a, int64_t b) { return (a + b - 1) / b; }

// The RAMB18's configurations: words by bits a word (the 9-, 18- and 36-bit ones with parity).
constexpr std::array<std::pair<int64_t, int>, 6> kAspects = {
    {{16384, 1}, {8192, 2}, {4096, 4}, {2048, 9}, {1024, 18}, {512, 36}}};

int64_t sum(const ResourceEstimate& estimate, int64_t (*of)(const ArithmeticUnits&)) {
  int64_t total = 0;
  for (const ArithmeticUnits& unit : estimate.units) total += unit.count * of(unit);
  return total;
}

}  // namespace

void ResourceEstimate::add(const ResourceEstimate& other, int64_t times) {
  for (MemoryArray array : other.memories) {
    array.count *= times;
    if (array.count > 0) memories.push_back(array);
  }
  for (ArithmeticUnits unit : other.units) {
    unit.count *= times;
    if (unit.count > 0) units.push_back(unit);
  }
}

int64_t ResourceEstimate::memoryBits() const {
  int64_t bits = 0;
  for (const MemoryArray& array : memories) bits += array.bits();
  return bits;
}

int64_t ResourceEstimate::blockRamBits() const {
  int64_t bits = 0;
  for (const MemoryArray& array : memories)
    if (array.depth > kDistributedDepth) bits += array.bits();
  return bits;
}

int64_t ResourceEstimate::blockRams() const {
  int64_t rams = 0;
  for (const MemoryArray& array : memories)
    rams += array.count * blockRamsOf(array.depth, array.width);
  return rams;
}

int64_t ResourceEstimate::unitCount(ArithmeticKind kind) const {
  int64_t count = 0;
  for (const ArithmeticUnits& unit : units)
    if (unit.kind == kind) count += unit.count;
  return count;
}

int64_t ResourceEstimate::dsp48e() const { return sum(*this, &dsp48eOf); }
int64_t ResourceEstimate::luts() const { return sum(*this, &lutsOf); }

int64_t blockRamsOf(int64_t depth, int width) {
  if (depth <= kDistributedDepth || width <= 0) return 0;
  int64_t fewest = -1;
  for (const auto& [words, bits] : kAspects) {
    const int64_t rams = ceilDiv(depth, words) * ceilDiv(width, bits);
    if (fewest < 0 || rams < fewest) fewest = rams;
  }
  return fewest;
}

int64_t dsp48eOf(const ArithmeticUnits& unit) {
  if (unit.kind != ArithmeticKind::Multiplier) return 0;
  // A binary32 multiplier multiplies its 24-bit significands.
  const bool float32 = unit.number == NumberKind::Float;
  const int64_t a = float32 ? 24 : unit.width;
  const int64_t b = float32 ? 24 : unit.otherWidth > 0 ? unit.otherWidth : unit.width;
  return std::min(ceilDiv(a, 25) * ceilDiv(b, 18), ceilDiv(b, 25) * ceilDiv(a, 18));
}

int64_t lutsOf(const ArithmeticUnits& unit) {
  if (unit.number == NumberKind::Float) {
    switch (unit.kind) {
      case ArithmeticKind::Adder: return 390;
      case ArithmeticKind::Multiplier: return 80;
      case ArithmeticKind::Divider: return 800;
      case ArithmeticKind::Comparator: return 40;
    }
  }
  switch (unit.kind) {
    case ArithmeticKind::Adder:
    case ArithmeticKind::Comparator: return unit.width;
    case ArithmeticKind::Multiplier: return 0;
    case ArithmeticKind::Divider: return int64_t{unit.width} * unit.width;
  }
  return 0;
}

const char* toString(ArithmeticKind kind) {
  switch (kind) {
    case ArithmeticKind::Adder: return "adder";
    case ArithmeticKind::Multiplier: return "multiplier";
    case ArithmeticKind::Divider: return "divider";
    case ArithmeticKind::Comparator: return "comparator";
  }
  return "?";
}

const char* toString(NumberKind number) { return number == NumberKind::Float ? "float" : "fixed"; }

}  // namespace rtu
