#pragma once
// The golden model of seed 003's BVH core on a host's ray records (issue 27): each record traced
// through a BVH image by the untimed shell of the BVH kind (kinds/bvh/bvh_kind.h), in the image's
// own space. A BVH image carries no model headers yet, so a record must name model address 0.

#include <string>
#include <vector>

#include "kinds/bvh/bvh_kind.h"
#include "rtu/ray_record.h"

namespace rtu {

struct BvhGoldenRun {
  std::vector<BvhResult> results;  // in record order; idWord = the record's id
  double seconds = 0;              // host time of the traversals
};

// Throws std::runtime_error naming `raysPath` and the record for a model address other than 0.
BvhGoldenRun traceBvhGolden(const std::vector<uint32_t>& image, const std::vector<RayRecord>& rays,
                            const std::string& raysPath, TriangleTest triangleTest);

}  // namespace rtu
