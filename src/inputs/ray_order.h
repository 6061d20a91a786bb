#pragma once
// The order a workload's ray records are written in (issue 32), since the order decides how
// coherent consecutive rays are: as generated (pixel order: hit by hit, then light or sample),
// shuffled (a wavefront renderer's queues mix rays of the whole frame), or sorted by direction
// octant, then by origin along a Morton curve (as ray-sorting hardware groups rays). Ids are kept,
// so results still map back to pixels.

#include <cstdint>
#include <string>
#include <vector>

#include "rtu/ray_record.h"

namespace rtu {

enum class RayOrder { Pixel, Shuffled, Sorted };

// "pixel", "shuffled" or "sorted"; throws std::invalid_argument naming the choices.
RayOrder parseRayOrder(const std::string& text);
const char* toString(RayOrder order);

// Reorders `rays` in place; Shuffled is a Fisher-Yates shuffle drawn from `seed`, Sorted is stable
// on a key of the direction's octant (sign bits x, y, z) and the origin's Morton code at 10 bits
// per axis within the rays' bounding box.
void orderRays(std::vector<RayRecord>& rays, RayOrder order, uint64_t seed);

}  // namespace rtu
