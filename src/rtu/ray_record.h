#pragma once
// The thesis's input ray packet (section 5.2): a world-space ray and the model to trace, in the
// float32 the host sends. Every kind's job manager starts from it: the transform into the model's
// space is shared (model_transform.h); what follows is the kind's (for SVO, t-values against its
// cube: kinds/svo/ray_transform.h).

#include <array>
#include <cstdint>

#include "geometry/ray.h"
#include "rtu/ray_span.h"

namespace rtu {

// Ray ids have 28 bits: the job manager packs the SVO direction coefficient into bits 30:28 of the
// job word beside it.
constexpr uint32_t kMaxRayId = (1u << 28) - 1;
// Bounds that keep every kind's job set-up of a valid ray finite (kinds/svo/ray_transform.h).
constexpr float kMaxModelCoordinate = 0x1p64f;  // |translation| and |ray components|

struct RayRecord {
  uint32_t id = 0;  // 28 bits
  std::array<float, 3> origin{0.0f, 0.0f, 0.0f};
  std::array<float, 3> direction{0.0f, 0.0f, 1.0f};
  uint32_t modelAddress = 0;     // word address of the model header
  RaySpan span = RaySpan::Line;  // word 0, bits 31:30 (rtu/ray_span.h)

  static constexpr const char* kName = "ray record";

  // Word 0: the id and the span's bits.
  uint32_t idWord() const;

  // Throws std::runtime_error for an id over 28 bits, a NaN or infinite component, a component
  // beyond kMaxModelCoordinate, or a zero direction.
  void validate() const;
};

// The record for a double-precision ray: direction normalised in double, then rounded to float32.
RayRecord makeRayRecord(uint32_t id, const Ray& ray, uint32_t modelAddress);

// Word 0 of a record read back: the id (bits 27:0, the rest checked by validate()) and the span
// (bits 31:30). Throws std::runtime_error when both span bits are set.
RayRecord recordOfWord0(uint32_t word);

}  // namespace rtu
