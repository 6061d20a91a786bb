#pragma once
// A look at an OBJ file's numbers before assimp reads it: assimp's fast_atof reads what is not a
// decimal number as something else without a word (the hexadecimal float 0x1p3 as 0, not 8), so
// the mesh would silently be another model (issue 33).

#include <string>

namespace rtu {

// When `path` ends in .obj (any case), requires every value of its v, vn, vt and vp lines to be a
// decimal number ([+-]digits[.digits][e[+-]digits]). Throws std::runtime_error naming `path`,
// the line and the value. Other files pass unchecked.
void checkObjNumbers(const std::string& path);

}  // namespace rtu
