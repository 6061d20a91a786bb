#pragma once
// Seed 001's scene file (S1 §2.3 L109-129, §3.3 p.20-21 L391-431; R1 SOFTWARE/src/scene/kdtree.cpp
// dump_*; specs/001 §4): big-endian, five sections, each a 32-bit count of the 32-bit words that
// follow (S1 says bytes; R1's writer and scene_loader.sv count words: reading K3), each padded
// with zero bytes to a word:
//
// | section  | payload                                                                         |
// |----------|---------------------------------------------------------------------------------|
// | nodes    | N nodes of 48 bits (narrow) or 64 bits (wide), depth first                      |
// | lists    | S triangle ids of 16 bits (narrow) or 32 bits (wide), leaves in node order       |
// | UTTM     | per triangle 9 words: 12 float24 (uttm.h)                                       |
// | colours  | per triangle 5 words: ambient r, g, b and the normal x, y, z as float24, then     |
// |          | specular[0] as float16 (vertex 0's normal in world space, not x/y swapped)       |
// | box      | 6 binary32: y_min, x_min, z_min, y_max, x_max, z_max (world) = hardware x, y, z |
//
// A narrow interior node: [47:46] axis in hardware space (00 x, 01 y, 10 z), [45:18] the split's
// binary32 bits 31:4 (truncated; reading K2), [17:2] the high (right, above) child, [1] the low
// child is empty, [0] the high child is empty; the low child is the next node (S1 §2.6.7 L230 and
// R1; §3.3.1 L403 says the reverse: reading K1). A leaf: [47:46] 11, [45:30] list index,
// [29:24] triangle count, [23:0] zero. The wide variant (rtusim's, for scenes past the narrow
// fields): interior [63:62] axis, [61:30] the whole split, [29:2] high child, [1], [0] flags; leaf
// [63:62] 11, [61:34] list index, [33:22] count, [21:0] zero.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "kinds/kd/pbrt_kd_builder.h"
#include "kinds/kd/uttm.h"

namespace rtu {

enum class TrayRacerFormat : uint8_t { Narrow, Wide };

// A node in hardware space, as the file holds it.
struct TrayRacerNode {
  bool leaf = false;
  uint32_t axis = 0;       // hardware axis: 0 x, 1 y, 2 z (world y, x, z)
  uint32_t splitBits = 0;  // binary32 bits; narrow: bits 3:0 zero
  uint32_t high = 0;       // the high child's node id; the low child is this node + 1
  bool lowEmpty = false, highEmpty = false;
  uint32_t listIndex = 0, count = 0;
  bool operator==(const TrayRacerNode& other) const;
};

// A triangle's shading record, the five colour-section words as stored.
using TrayRacerShade = std::array<uint32_t, 5>;

struct TrayRacerScene {
  std::vector<TrayRacerNode> nodes;
  std::vector<uint32_t> lists;
  std::vector<UttmWords> uttms;
  std::vector<TrayRacerShade> shades;
  std::array<float, 6> box{};  // hardware x, y, z min then max
};

// What the file's colour section says of each triangle (R1: the model's material; K11).
struct TrayRacerMaterial {
  glm::dvec3 ambient{0.0};
  double specular = 0;
};

// The file from a build over `corners` (three world-space vertices per triangle, in double, the
// build's triangle order), `normals` (each triangle's vertex-0 normal in world space) and one
// material for all; the unit-triangle matrices with `column` (uttm.h: R1's by default).
TrayRacerScene makeTrayRacerScene(const KdBuild& build, const std::vector<glm::dvec3>& corners,
                                  const std::vector<glm::dvec3>& normals,
                                  const TrayRacerMaterial& material,
                                  KdMatrixColumn column = KdMatrixColumn::NormalMinusC);

// The normal a triangle's shading record holds (vertex 0's, in world space), its float24 fields
// padded to binary32 as the shader reads them.
glm::dvec3 trayRacerNormal(const TrayRacerShade& shade);

// Throws std::invalid_argument naming the field when a node, id or count does not fit `format`.
std::vector<uint8_t> writeTrayRacerScene(const TrayRacerScene& scene, TrayRacerFormat format);
// Throws std::runtime_error naming the section and word when the bytes are not a sound file.
TrayRacerScene readTrayRacerScene(const std::vector<uint8_t>& bytes, TrayRacerFormat format);

// The final hardware's capacities (specs/001 §4.8: the cache BRAMs): 4096 nodes, 16384 list
// entries, 1024 triangles, 63 triangles in a leaf. One message per limit exceeded, naming it.
std::vector<std::string> trayRacerCapacityWarnings(const TrayRacerScene& scene);

// Hardware space from world space: x and y swapped (R1 matrix.cpp and dump_aabb; reading K4).
inline glm::dvec3 toHardwareSpace(const glm::dvec3& world) { return {world.y, world.x, world.z}; }

}  // namespace rtu
