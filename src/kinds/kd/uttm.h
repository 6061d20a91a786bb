#pragma once
// Seed 001's unit-triangle transformation matrices (S1 §3.3.2 p.20 L411-425, after Schmittler et
// al.): the affine map that takes a triangle's A to (1, 0, 0), B to (0, 1, 0) and C to the origin,
// so that the INT unit finds t from the transformed ray's z and the barycentrics u (weight of A)
// and v (weight of B) from its x and y. As R1 computes it (SOFTWARE/src/math/matrix.cpp,
// int_cacheline_t; facts only): in double, on the vertices in hardware space (x and y swapped),
// as the inverse of the 4x4 matrix [A - C, B - C, N - C, C; 0 0 0 1] whose third column is the
// unit normal N = (C - A) x (B - A) / |...| taken as a point, minus C. The inverse is the textbook
// cofactor expansion over the determinant, every sum in the expansion's term order; with the last
// row (0, 0, 0, 1) its other terms are exact zeros and drop out (see uttm.cpp).
//
// That third column makes the matrix singular for every triangle whose plane lies at distance 1
// from the origin along N (N - C is then in the plane): its entries are infinities and NaNs and
// the INT unit never hits it. A voxel scene over the cube [-1, 1]^3 has all its outer faces so
// (docs/triangles.md, "Known defect"). KdMatrixColumn::Normal, rtusim's correction, takes N itself
// as the third column, as Schmittler et al.'s unit-triangle transform does: never in the plane, so
// never singular. The INT unit is the same for both (z' is 0 on the plane either way; only its
// scale, which t's division cancels, differs).
//
// Stored (specs/001 §4.4): each of the 12 entries cast to float (RNE), then truncated to float24,
// packed most significant first, m00 m01 m02 m10 m11 m12 m20 m21 m22 tx ty tz: 288 bits, 9 words.

#include <array>
#include <cstdint>
#include <string>

#include <glm/vec3.hpp>

namespace rtu {

struct UnitTriangleMatrix {
  std::array<std::array<double, 3>, 3> m{};  // m[row][column]
  std::array<double, 3> t{};                 // translation
};

constexpr int kUttmWords = 9;
constexpr int kUttmEntries = 12;
using UttmWords = std::array<uint32_t, kUttmWords>;

// The matrix's third column: R1's N - C, or N (accel.kd_matrix r1 or normal).
enum class KdMatrixColumn : uint8_t { NormalMinusC, Normal };

// "r1" -> NormalMinusC, "normal" -> Normal; throws std::invalid_argument naming accel.kd_matrix for
// other text.
KdMatrixColumn parseKdMatrixColumn(const std::string& name);

// A, B, C in hardware space.
UnitTriangleMatrix unitTriangleMatrix(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                                      KdMatrixColumn column = KdMatrixColumn::NormalMinusC);

// The 12 entries as float24 fields, packed; and back as the binary32 values the INT unit reads
// (each field padded with 8 zero bits), in the order above.
UttmWords packUttm(const UnitTriangleMatrix& matrix);
std::array<float, kUttmEntries> unpackUttm(const UttmWords& words);

}  // namespace rtu
