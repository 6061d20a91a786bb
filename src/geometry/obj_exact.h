#pragma once
// A strict OBJ reader in double, for builds that must reproduce another program's output bit for
// bit (seed 001's scene files: R1 parses OBJ in double, assimp in float; reading K7). It reads
// `v`, `vn` and `f` and ignores every other statement (`vt`, `g`, `s`, `usemtl`, comments). A
// face has 3 or 4 corners, `i`, `i/t`, `i//n` or `i/t/n` with 1-based indices; a quad becomes
// the triangles (0, 1, 2) and (2, 3, 0), in file order, as R1's loader splits it
// (SOFTWARE/src/scene/mesh.cpp). Numbers are parsed by strtod, correctly rounded as iostream's
// `>>` does. Anything else (a bad number, an index out of range, a face of 5 corners) is a
// std::runtime_error naming the file and line.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/triangle_mesh.h"

namespace rtu {

struct ObjMesh {
  TriangleMesh mesh;                                  // positions, unjoined: one per `v` line
  std::vector<glm::dvec3> normals;                    // one per `vn` line
  std::vector<std::array<int32_t, 3>> cornerNormals;  // per triangle, -1 where a corner has none
};

ObjMesh readObjExact(const std::string& path);
// The same from text already in memory; `name` goes into error messages.
ObjMesh parseObjExact(const std::string& text, const std::string& name);

}  // namespace rtu
