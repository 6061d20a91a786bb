#pragma once
// Which part of its line a ray traces (issue 32). The thesis' rays (primary rays from a camera
// outside the model) take every hit on the line from where it enters the model's cube; a
// secondary ray starts on a surface and must not find what lies behind its origin, and a shadow
// or occlusion ray needs only whether anything lies between its origin and its end. t is in the
// units of the record's direction: t = 0 at the origin, t = 1 at origin + direction.
//
// A ray record carries the span in bits 31:30 of its first word (docs/inputs-jobs.md); the job
// word a kind's result returns keeps bit 31 for an any-hit ray, so the host and the statistics
// tell them apart.

#include <cstdint>

namespace rtu {

enum class RaySpan : uint8_t {
  Line,    // every hit on the line, the nearest from the cube's entry (the thesis' rays)
  Ahead,   // the nearest hit at t >= 0 (a reflected or diffuse ray)
  AnyHit,  // whether anything is hit within t in [0, 1]: the traversal ends at the first hit
};

constexpr uint32_t kAnyHitBit = 1u << 31;  // the ray record's word 0: RaySpan::AnyHit
constexpr uint32_t kAheadBit = 1u << 30;   // the ray record's word 0: RaySpan::Ahead

}  // namespace rtu
