#pragma once
// A BVH image in memory as a model the RTU traces world-space rays against (bvh_job_setup.h): the
// image at word 0, then a model header (rtu/model_header.h) naming it, placed in the world.

#include <cstdint>
#include <vector>

#include "rtu/model_header.h"

namespace rtu {

// Appends to `words` (a BVH image, its header at word 0) a model header for the image placed by
// `placement` and returns the header's word address (the old size). Throws as makeModelHeader.
inline uint32_t appendBvhModelHeader(std::vector<uint32_t>& words,
                                     const ModelPlacement& placement) {
  return appendModelHeader(words, placement, 0);
}

}  // namespace rtu
