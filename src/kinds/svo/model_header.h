#pragma once
// The placement of an animated model (thesis sections 4.3 and 6.2.1): 16 words in SVO memory at
// the model address a ray record names, which the job manager fetches to move the ray into the
// model's space. Layout, little-endian 32-bit words:
//   0..2    translation T (float32 x, y, z)
//   3..11   inverse rotation R^T, row-major (float32)
//   12..14  inverse scale 1/S (float32 x, y, z)
//   15      word address of the model's root descriptor
// The model's cube [-1,1]^3 sits in the world at p_world = R (S p_model) + T, so a world point
// maps back as p_model = (1/S) (R^T (p_world - T)).

#include <array>
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "kinds/svo/svo_memory.h"

namespace rtu {

constexpr size_t kModelHeaderWords = 16;
using ModelHeaderWords = std::array<uint32_t, kModelHeaderWords>;

// Bounds that keep the job set-up of every valid ray finite (see ray_transform.h).
constexpr float kMaxModelCoordinate = 0x1p64f;  // |translation| and |ray components|
constexpr float kMinInverseScale = 0x1p-32f;    // 1/S within [2^-32, 2^32]
constexpr float kMaxInverseScale = 0x1p32f;

// A model's placement in world space, as an animation system would hold it.
struct ModelPlacement {
  glm::dvec3 translation{0.0};
  glm::dmat3 rotation{1.0};  // proper rotation (orthonormal, determinant +1)
  glm::dvec3 scale{1.0};     // per model axis, positive
};

// R = Rz(z) Ry(y) Rx(x): about the world x axis first, then y, then z; degrees, right-handed.
glm::dmat3 rotationFromEulerDegrees(const glm::dvec3& degrees);

// The header's contents, in the float32 the job manager computes with.
struct ModelHeader {
  std::array<float, 3> translation{0.0f, 0.0f, 0.0f};
  std::array<float, 9> inverseRotation{1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  std::array<float, 3> inverseScale{1.0f, 1.0f, 1.0f};
  uint32_t root = 0;

  // Throws std::runtime_error naming the field for: a NaN or infinite value, |T| above
  // kMaxModelCoordinate, 1/S outside [kMinInverseScale, kMaxInverseScale], or an inverse rotation
  // that is not a proper rotation (R^T R differs from I by more than 1e-5, or det <= 0).
  void validate() const;
};

// Rounds the placement to float32 (R^T and 1/S computed in double first). Throws
// std::invalid_argument for a scale outside [2^-32, 2^32] or a header that fails validate().
ModelHeader makeModelHeader(const ModelPlacement& placement, uint32_t root);

ModelHeaderWords encodeModelHeader(const ModelHeader& header);
// Unpacks the words as the hardware does, without checks.
ModelHeader decodeModelHeader(const ModelHeaderWords& words);
// Decodes and validates the header at `address`; throws std::runtime_error naming the address
// when the header or the root it names lies outside the memory, or validate() fails.
ModelHeader readModelHeader(const WordMemory& memory, uint32_t address);

}  // namespace rtu
