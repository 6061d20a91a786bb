#pragma once
// File form of a BIH memory image (.bih): its words, little-endian, the 16-word header first, so
// that a file names its own format (bih_image.h, kBihMagic), its arithmetic and its section bases.

#include <string>
#include <vector>

#include "kinds/bih/bih_image.h"

namespace rtu {

// Whether `words` begin with a BIH image's magic word.
bool looksLikeBihImage(const std::vector<uint32_t>& words);

// Reads and validates (bih_validator.h) a BIH image, with its capacity warnings. Throws
// std::runtime_error naming `path` when the file cannot be read, is not a whole number of words,
// or the image is not sound: the message lists the first problems found.
BihImage readBihFile(const std::string& path);
// Throws std::runtime_error naming `path` when it cannot be written.
void writeBihFile(const std::string& path, const BihImage& image);

}  // namespace rtu
