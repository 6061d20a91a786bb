#pragma once
// The Tray Racer team's files (R1, github.com/ryanmacdonald/18-545 at 81a34cd) for the tests that
// read them at run time: scripts/extract_trayracer.sh extracts them into the folder
// RTUSIM_TRAYRACER_DIR names (R1 has no licence, so rtusim never holds them).

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/obj_exact.h"
#include "kinds/kd/trayracer_scene.h"

namespace rtu {

// The folder, or null when the variable is unset (the tests then warn and check nothing).
inline const char* trayRacerDir() { return std::getenv("RTUSIM_TRAYRACER_DIR"); }

inline std::vector<uint8_t> readBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("cannot open " + path);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// R1's SOFTWARE/scenes/venus.scene: elephav.obj, its first 1023 triangles (the loader's cap),
// placed at (1, 0.5, 1) with scale 0.01 (as R1's 4x4 model matrix computes a point in double:
// s x + p, the zero terms exact), material "magenta" (ambient 1, 0, 1; specular 0.4). The corners
// are three per triangle in world space, in the file's triangle order; the normals vertex 0's.
struct ElephantSource {
  std::vector<glm::dvec3> corners, normals;
};

inline ElephantSource elephantSource(const std::string& dir) {
  const ObjMesh obj = readObjExact(dir + "/SOFTWARE/models/elephav.obj");
  const glm::dvec3 position(1.0, 0.5, 1.0), scale(0.01);
  ElephantSource source;
  for (size_t t = 0; t < 1023; ++t) {
    for (int k = 0; k < 3; ++k)
      source.corners.push_back(scale * obj.mesh.vertices[obj.mesh.triangles[t][k]] + position);
    const int32_t n = obj.cornerNormals[t][0];
    source.normals.push_back(n < 0 ? glm::dvec3(0.0) : scale * obj.normals[n]);
  }
  return source;
}

inline TrayRacerScene buildElephant(const std::string& dir) {
  const ElephantSource source = elephantSource(dir);
  const KdBuild build = buildPbrtKd(pbrtTriangleBoxes(source.corners), PbrtKdParameters{});
  return makeTrayRacerScene(build, source.corners, source.normals, {{1.0, 0.0, 1.0}, 0.4});
}

}  // namespace rtu
