#pragma once
// The placement of an animated model (thesis sections 4.3 and 6.2.1): 16 words in memory at the
// model address a ray record names, which the job manager fetches to move the ray into the
// model's space (rtu/model_transform.h). Shared by every kind; word 15 is the kind's entry to its
// model (SVO: the root descriptor; BVH: the image's header). Layout, little-endian 32-bit words:
//   0..2    translation T (float32 x, y, z)
//   3..11   inverse rotation R^T, row-major (float32)
//   12..14  inverse scale 1/S (float32 x, y, z)
//   15      word address of the model's root (SVO: root descriptor; BVH: image header)
// The model (SVO: its cube [-1,1]^3) sits in the world at p_world = R (S p_model) + T.

#include <array>
#include <cstdint>
#include <vector>

#include "rtu/model_transform.h"
#include "rtu/word_memory.h"

namespace rtu {

constexpr size_t kModelHeaderWords = 16;
using ModelHeaderWords = std::array<uint32_t, kModelHeaderWords>;

// The header's contents: the model's transform (shared by every kind, rtu/model_transform.h) and
// its root.
struct ModelHeader : ModelTransform {
  uint32_t root = 0;
};

// makeModelTransform's header for `root` (std::invalid_argument as it).
ModelHeader makeModelHeader(const ModelPlacement& placement, uint32_t root);

ModelHeaderWords encodeModelHeader(const ModelHeader& header);
// Appends to `words` (an image) the encoded header of a model placed at `placement` whose structure
// starts at `root`, and returns the header's word address (the old size). Throws as
// makeModelHeader.
uint32_t appendModelHeader(std::vector<uint32_t>& words, const ModelPlacement& placement,
                           uint32_t root);
// Unpacks the words as the hardware does, without checks.
ModelHeader decodeModelHeader(const ModelHeaderWords& words);
// Decodes and validates (ModelTransform::validate) the header at `address`; throws
// std::runtime_error naming the address when the header or the root it names lies outside the
// memory, or validate() fails.
ModelHeader readModelHeader(const WordMemory& memory, uint32_t address);

}  // namespace rtu
