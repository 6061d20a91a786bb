#include "trace/trace_writer.h"

#include <algorithm>

namespace rtu {

std::string bitString(uint64_t value, int width) {
  std::string bits(static_cast<size_t>(width), '0');
  for (int i = 0; i < width; ++i)
    if (value >> i & 1) bits[static_cast<size_t>(width - 1 - i)] = '1';
  return bits;
}

std::optional<TraceTimeUnit> TraceTimeUnit::ofPicoseconds(uint64_t ps) {
  if (ps == 0) return std::nullopt;
  int exponent = -12;
  for (; ps % 10 == 0; ps /= 10) ++exponent;
  if (ps != 1) return std::nullopt;
  return TraceTimeUnit{exponent};
}

uint64_t TraceTimeUnit::picoseconds() const {
  uint64_t ps = 1;
  for (int e = -12; e < exponent; ++e) ps *= 10;
  return ps;
}

uint64_t TraceTimeUnit::viewerFactor() const {
  uint64_t factor = 1;
  for (int i = 0; i < (exponent + 12) % 3; ++i) factor *= 10;
  return factor;
}

std::string TraceTimeUnit::vcdTimescale() const {
  static const char* const kUnits[] = {"ps", "ns", "us", "ms", "s"};
  const int steps = exponent + 12;  // thousands and the rest above 1 ps
  const int thousands = std::min(steps / 3, 4);
  std::string factor = "1";
  for (int i = thousands * 3; i < steps; ++i) factor += '0';
  return factor + kUnits[thousands];
}

std::unique_ptr<TraceWriter> openTraceWriter(const std::string& path, TraceTimeUnit unit) {
  const std::string fst = ".fst";
  const bool isFst =
      path.size() > fst.size() && path.compare(path.size() - fst.size(), fst.size(), fst) == 0;
  return isFst ? openFstWriter(path, unit) : openVcdWriter(path, unit);
}

}  // namespace rtu
