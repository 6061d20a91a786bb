#pragma once
// The scene on seed 004's n-bit integer grid (S4 §2.1.2 p.25 L276-287): moved to the positive
// octant and scaled by one factor so that the box's lower corner is 0 and its longest side spans
// 2^n - 1 grid units; vertices rounded to grid integers. A ray is clipped to the scene box in
// double before it is quantised ("rays starting outside the bounding box ... must be clipped to
// the bounding box prior to quantization", L287), so its origin is a grid point; its direction
// becomes m-bit fixed point and its inverse direction (m+C)-bit (§2.4 L415-419).

#include <array>
#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "geometry/aabb.h"
#include "geometry/ray.h"
#include "kinds/bih/fixed_format.h"

namespace rtu {

using GridPoint = std::array<int64_t, 3>;

// A ray as the fixed-point kernels and the BIH read it. t along it is in grid units: omega is
// (close to) unit length, so t = 1 is one grid unit of travel.
struct GridRay {
  GridPoint origin{};  // n-bit grid coordinates of the clipped origin
  GridPoint omega{};   // m-bit signed, scale 2^(m-1), the L2-unit direction (plan reading C3)
  GridPoint idir{};    // the inverse direction, (m+C) bits (inverseDirection)
  double tClip = 0;    // where the world ray enters the box, in units of its direction
  double worldPerGridUnit = 0;  // 1 / (scale |d|): a grid unit of t in units of the direction
  // A grid t as t along the world ray: t_clip + t_grid / (scale |d|).
  double worldT(int64_t tGrid) const {
    return tClip + static_cast<double>(tGrid) * worldPerGridUnit;
  }
};

// Grid units kept free around the scene's vertices (rtusim's, not the seed's: S4 scales the
// vertices' own box to the grid). A ray from outside is clipped to the grid's box, so it starts on
// a face of that box; a triangle lying in that face (a voxel face, a model's flat side) would be
// at t = 0 there, which the kernels refuse (t > 0; t >= 1 in the VHDL variant), and the ray would
// pass through it. Two units, the size of the seed's own secondary-ray offset (S4 L468), keep
// every triangle at least 1.5 units (after the origin's rounding) ahead of a clipped origin.
constexpr int kGridMargin = 2;

// The box whose grid holds `vertices` kGridMargin grid units inside each of its faces: `vertices`
// widened on every side by kGridMargin L / (2^n - 1 - 2 kGridMargin), L its longest side (not
// widened on a grid of at most 4 kGridMargin units, n <= 3).
Aabb<double> gridBoxAround(const Aabb<double>& vertices, const FixedTriangleFormat& format);

class SceneGrid {
 public:
  // The grid of `box` (the scene's vertices' box, geometry/ray_sets.h meshBounds). Throws
  // std::invalid_argument for an empty or flat-to-a-point box, a bound that is not finite, or a
  // format validateFixedTriangleFormat refuses.
  SceneGrid(const Aabb<double>& box, const FixedTriangleFormat& format);

  const FixedTriangleFormat& format() const { return format_; }
  const Aabb<double>& box() const { return box_; }
  // Grid units per world unit: (2^n - 1) / the box's longest side.
  double scale() const { return scale_; }

  // (p - lower) scale rounded half to even (plan reading C4; the product in double, under 2^-22
  // grid units from exact for n <= 30) and kept in [0, 2^n - 1].
  GridPoint quantise(const glm::dvec3& p) const;
  // The ray clipped to the box from t = 0 on, then quantised; none when it misses the box. Its
  // direction is normalised in double, then each component rounded half to even at scale 2^(m-1)
  // and saturated to [-2^(m-1), 2^(m-1) - 1] (+1 is not representable, C2). Throws
  // std::invalid_argument for a zero or non-finite direction or a non-finite origin.
  std::optional<GridRay> quantise(const Ray& ray) const;

 private:
  FixedTriangleFormat format_;
  Aabb<double> box_;
  double scale_;
};

// The inverse of one direction code (plan reading C14). Vhdl: trunc(2^(m-1+C) / ω), i.e. 1/ω
// with C fractional bits, saturated to the (m+C)-bit range ±(2^(m+C-1) - 1) (only |ω| = one code
// exceeds it). C99 as printed: `nom = 1ULL << (m + C); omega_inv = nom / omega` (S4 §2.4 p.30
// L427-428), i.e. 2^(C+1)/ω, t doubled; the listing keeps it in a long long. ω = 0 (+0 and -0
// alike) is taken as the smallest positive code, so an axis the ray does not move along gets the
// largest positive inverse.
int64_t inverseDirection(int64_t omega, const FixedTriangleFormat& format);

}  // namespace rtu
