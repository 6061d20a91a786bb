#pragma once
// The placement of an animated model and the job manager's move of a world-space ray into the
// model's space (thesis section 6.2.1, stages one and two): shared by every kind of core, whose
// job set-up goes on from the model-space ray (for SVO: kinds/svo/ray_transform.h).
//
// The model sits in the world at p_world = R (S p_model) + T, so a world point maps back as
// p_model = (1/S) (R^T (p_world - T)). Every value is float32, every operation rounds to nearest
// even on its own (a multiply-add is a multiply, rounded, then an add, rounded: no fused
// multiply-add; the project builds in ISO C++ mode, where GCC does not contract, and each
// operation is its own statement). With T, R^T (rows m_i) and s = 1/S:
//
//   1. v = o - T                                   (per axis)
//   2. q_i = (m_i0 v_0 + m_i1 v_1) + m_i2 v_2,      o'_i = s_i q_i
//   3. e_i = (m_i0 d_0 + m_i1 d_1) + m_i2 d_2,      d'_i = s_i e_i
//
// The direction is not normalised: t keeps the world units of d.

#include <array>
#include <cstdint>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "rtu/ray_record.h"

namespace rtu {

constexpr float kMinInverseScale = 0x1p-32f;  // 1/S within [2^-32, 2^32]
constexpr float kMaxInverseScale = 0x1p32f;

// A model's placement in world space, as an animation system would hold it.
struct ModelPlacement {
  glm::dvec3 translation{0.0};
  glm::dmat3 rotation{1.0};  // proper rotation (orthonormal, determinant +1)
  glm::dvec3 scale{1.0};     // per model axis, positive
};

// R = Rz(z) Ry(y) Rx(x): about the world x axis first, then y, then z; degrees, right-handed.
glm::dmat3 rotationFromEulerDegrees(const glm::dvec3& degrees);

// The placement inverted, in the float32 the job manager computes with.
struct ModelTransform {
  std::array<float, 3> translation{0.0f, 0.0f, 0.0f};
  std::array<float, 9> inverseRotation{1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f};
  std::array<float, 3> inverseScale{1.0f, 1.0f, 1.0f};

  // Throws std::runtime_error naming the field for: a NaN or infinite value, |T| above
  // kMaxModelCoordinate, 1/S outside [kMinInverseScale, kMaxInverseScale], or an inverse rotation
  // that is not a proper rotation (R^T R differs from I by more than 1e-5, or det <= 0).
  void validate() const;
};

// Rounds the placement to float32 (R^T and 1/S computed in double first). Throws
// std::invalid_argument for a scale outside [2^-32, 2^32] or a transform that fails validate().
ModelTransform makeModelTransform(const ModelPlacement& placement);

// A ray in the model's space, float32.
struct ModelSpaceRay {
  std::array<float, 3> origin{}, direction{};
};

// Steps 1 to 3 above. `record` and `transform` must be valid (the hardware checks neither): then
// |o'| and |d'| stay below 2^100.
ModelSpaceRay toModelSpace(const RayRecord& record, const ModelTransform& transform);

}  // namespace rtu
