#pragma once
// Whole-file reads and writes of little-endian 32-bit words, shared by every binary format.

#include <cstdint>
#include <string>
#include <vector>

namespace rtu {

// Throws std::runtime_error naming `path` when it cannot be read or its size is not a multiple
// of `recordBytes` (what = the kind of file, for the message).
std::vector<uint32_t> readWordFile(const std::string& path, size_t recordBytes,
                                   const std::string& what);
void writeWordFile(const std::string& path, const std::vector<uint32_t>& words);

}  // namespace rtu
