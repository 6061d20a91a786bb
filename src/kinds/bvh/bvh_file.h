#pragma once
// File form of a BVH memory image (.bvh): its words, little-endian, the 16-word header first, so
// that a file names its own format (bvh_image.h, kBvhMagic) and carries its section bases.

#include <string>
#include <vector>

#include "kinds/bvh/bvh_image.h"

namespace rtu {

// Whether `words` begin with a BVH image's magic word.
bool looksLikeBvhImage(const std::vector<uint32_t>& words);

// Reads and validates (bvh_validator.h) a BVH image. Throws std::runtime_error naming `path` when
// the file cannot be read, is not a whole number of words, or the image is not sound: the message
// lists the first problems found.
BvhImage readBvhFile(const std::string& path);
// Throws std::runtime_error naming `path` when it cannot be written.
void writeBvhFile(const std::string& path, const BvhImage& image);

}  // namespace rtu
