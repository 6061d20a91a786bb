#pragma once
// Every file rtusim reads as an input is opened here (issue 33): it must be a regular file, and
// its size is known before a byte is read. A FIFO would block the open forever, a device such as
// /dev/zero never ends, and a directory "opens" with a size of 2^63 - 1: each is refused with a
// message naming the file and what it is instead ("'/dev/zero' is not a regular file (a
// character device)").

#include <cstdint>
#include <fstream>
#include <string>

namespace rtu {

// The size of the regular file at `path` (symbolic links followed); throws std::runtime_error
// naming `what` and `path` when it does not exist, cannot be read or is anything else.
uint64_t inputFileBytes(const std::string& path, const std::string& what);

// Opens the regular file at `path` in binary after the check above; `bytes` is its size.
std::ifstream openInputFile(const std::string& path, const std::string& what, uint64_t& bytes);

// The same for a file a run may not have written yet (a sweep's rows): a closed stream, which reads
// nothing, when nothing is at `path`.
std::ifstream openInputFileIfAny(const std::string& path, const std::string& what);

// The whole regular file at `path`, refused without reading when it is larger than `maxBytes`.
std::string readInputFile(const std::string& path, const std::string& what, uint64_t maxBytes);

// Configuration, sweep and scene files are read whole; the largest written by hand or by rtusim
// (a statistics file given as --config) is a few kilobytes.
constexpr uint64_t kMaxSettingsFileBytes = uint64_t{64} << 20;

}  // namespace rtu
