#include "trace/trace_writer.h"

namespace rtu {

std::string bitString(uint64_t value, int width) {
  std::string bits(static_cast<size_t>(width), '0');
  for (int i = 0; i < width; ++i)
    if (value >> i & 1) bits[static_cast<size_t>(width - 1 - i)] = '1';
  return bits;
}

std::unique_ptr<TraceWriter> openTraceWriter(const std::string& path) {
  const std::string fst = ".fst";
  const bool isFst =
      path.size() > fst.size() && path.compare(path.size() - fst.size(), fst.size(), fst) == 0;
  return isFst ? openFstWriter(path) : openVcdWriter(path);
}

}  // namespace rtu
