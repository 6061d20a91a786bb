#pragma once
// The BIH core's triangle tests, the traversal's template parameter: seed 004's two kernels
// (fixed_kernels.h) with the closest-hit rule each needs. C99's own `0 < t <= tBest` is the
// golden rule (S4 §2.3 L388-390): of equal t the later triangle wins. The VHDL unit has no such
// test (C9); its hits are reduced outside it by the same `t <= tBest`, keeping its t = 0.

#include <cstdint>

#include "kinds/bih/fixed_kernels.h"

namespace rtu {

struct C99Intersector {
  static constexpr const char* kName = "c99";
  FixedTest test(const FixedTriangleFormat& format, const GridRay& ray,
                 const ProjectedTriangle& triangle, int64_t tBest) const {
    return c99Test(format, ray, triangle, tBest);
  }
};

struct VhdlIntersector {
  static constexpr const char* kName = "vhdl";
  VhdlOptions options;
  FixedTest test(const FixedTriangleFormat& format, const GridRay& ray,
                 const ProjectedTriangle& triangle, int64_t tBest) const {
    FixedTest result = vhdlTest(format, ray, triangle, options);
    if (result.hit() && result.t > tBest) result.verdict = FixedVerdict::NotAhead;
    return result;
  }
};

// The kernel the image's formats are meant for (FixedTriangleFormat::listing): the registered
// kind's, one branch per test, the same in a whole run over one image.
struct ListingIntersector {
  static constexpr const char* kName = "listing";
  FixedTest test(const FixedTriangleFormat& format, const GridRay& ray,
                 const ProjectedTriangle& triangle, int64_t tBest) const {
    if (format.listing == FixedListing::Vhdl)
      return VhdlIntersector{}.test(format, ray, triangle, tBest);
    return C99Intersector{}.test(format, ray, triangle, tBest);
  }
};

}  // namespace rtu
