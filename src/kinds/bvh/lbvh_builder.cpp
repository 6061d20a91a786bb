#include "kinds/bvh/lbvh_builder.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "kinds/bvh/build_primitives.h"
#include "kinds/bvh/top_down_build.h"

namespace rtu {
namespace {

constexpr uint32_t kCells = 1024;  // 10 bits per axis

// The 10 bits of `v` spread to every third bit.
uint32_t spread(uint32_t v) {
  v &= 0x3ff;
  v = (v | (v << 16)) & 0x030000ff;
  v = (v | (v << 8)) & 0x0300f00f;
  v = (v | (v << 4)) & 0x030c30c3;
  v = (v | (v << 2)) & 0x09249249;
  return v;
}

// Each triangle's code: its box centre's cell in the centres' box, 0 on an axis without extent.
std::vector<uint32_t> codesOf(const BuildPrimitives& primitives) {
  Aabb<double> centres;
  for (const glm::dvec3& c : primitives.centres) centres.grow(c);
  std::vector<uint32_t> codes;
  codes.reserve(primitives.centres.size());
  for (const glm::dvec3& c : primitives.centres) {
    uint32_t cell[3];
    for (int k = 0; k < 3; ++k) {
      const double extent = centres.upper[k] - centres.lower[k];
      const double scaled = extent > 0 ? kCells * (c[k] - centres.lower[k]) / extent : 0;
      cell[k] = std::min(static_cast<uint32_t>(scaled), kCells - 1);
    }
    codes.push_back(mortonCode(cell[0], cell[1], cell[2]));
  }
  return codes;
}

}  // namespace

uint32_t mortonCode(uint32_t x, uint32_t y, uint32_t z) {
  return spread(x) << 2 | spread(y) << 1 | spread(z);
}

LbvhBuild buildLbvh(const BuildPrimitives& primitives, const LbvhConfig& config) {
  if (config.maxLeafSize < 1)
    throw std::invalid_argument("lbvh builder: the maximum leaf size must be at least 1");
  checkPrimitives(primitives, "lbvh");
  const std::vector<uint32_t> codes = codesOf(primitives);
  std::vector<uint32_t> refs(codes.size());
  std::iota(refs.begin(), refs.end(), 0u);
  std::sort(refs.begin(), refs.end(), [&](uint32_t a, uint32_t b) {
    return codes[a] < codes[b] || (codes[a] == codes[b] && a < b);
  });
  LbvhBuild result;
  // Sorted by code, a node's references need no reordering: only where to divide them.
  result.tree =
      buildTopDown(primitives, std::move(refs),
                   [&](std::vector<uint32_t>& sorted, const BuildNode& node) -> uint32_t {
                     if (node.count <= config.maxLeafSize) return 0;
                     const auto begin = sorted.begin() + node.first, end = begin + node.count;
                     const uint32_t first = codes[*begin], last = codes[*(end - 1)];
                     if (first == last) {
                       ++result.equalCodeSplits;
                       return node.count / 2;
                     }
                     const uint32_t bit = 1u << (31 - __builtin_clz(first ^ last));
                     const auto split = std::partition_point(begin, end, [&](uint32_t ref) {
                       return (codes[ref] & bit) == 0;
                     });
                     return static_cast<uint32_t>(split - begin);
                   });
  return result;
}

LbvhBuild buildLbvh(const TriangleMesh& mesh, const LbvhConfig& config) {
  return buildLbvh(buildPrimitives(mesh, "lbvh"), config);
}

}  // namespace rtu
