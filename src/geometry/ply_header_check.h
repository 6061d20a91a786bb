#pragma once
// A cheap look at a PLY file's header before assimp reads it: assimp's PLY reader spins
// forever on a header without end_header and misreads headers with binary garbage (issue 12).

#include <string>

namespace rtu {

// When the file at `path` starts with "ply" or "PLY" (assimp's magic numbers), requires its
// header to be printable ASCII (UTF-8 in comments), to end with an `end_header` line within the
// first 64 KiB, and every `element NAME COUNT` to have a decimal count no larger than the bytes
// after the header (each element takes at least one). An ASCII file's body must hold exactly the
// elements declared, one a line, each with the values its properties take (a list's count read
// from the line): a header declaring more vertices than held was read as another model. A binary
// file's body must hold exactly the bytes its elements take (each list's count read from the
// file), so that the counts agree with the file's size.
// Throws std::runtime_error naming `path` and the problem. Other files pass unchecked.
void checkPlyHeader(const std::string& path);

}  // namespace rtu
