#include "kinds/kd/uttm.h"

#include <cmath>
#include <stdexcept>

#include "kinds/kd/truncated_float.h"

namespace rtu {

KdMatrixColumn parseKdMatrixColumn(const std::string& name) {
  if (name == "r1") return KdMatrixColumn::NormalMinusC;
  if (name == "normal") return KdMatrixColumn::Normal;
  throw std::invalid_argument("accel.kd_matrix '" + name + "': r1 or normal");
}

UnitTriangleMatrix unitTriangleMatrix(const glm::dvec3& A, const glm::dvec3& B, const glm::dvec3& C,
                                      KdMatrixColumn column) {
  glm::dvec3 n((C.y - A.y) * (B.z - A.z) - (C.z - A.z) * (B.y - A.y),
               (C.z - A.z) * (B.x - A.x) - (C.x - A.x) * (B.z - A.z),
               (C.x - A.x) * (B.y - A.y) - (C.y - A.y) * (B.x - A.x));
  const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  n = glm::dvec3(n.x / length, n.y / length, n.z / length);
  // a[i][j] = row i + 1, column j + 1 of [A - C, B - C, N - C, C; 0 0 0 1].
  double a[4][4] = {{}, {}, {}, {0, 0, 0, 1}};
  for (int i = 0; i < 3; ++i) {
    a[i][0] = A[i] - C[i];
    a[i][1] = B[i] - C[i];
    a[i][2] = column == KdMatrixColumn::Normal ? n[i] : n[i] - C[i];
    a[i][3] = C[i];
  }
  // The adjugate by the textbook cofactor expansion: b_ij = the sum of three products minus three,
  // each written as the 1-based row-column digits of its factors ("223344" = a22 a33 a44), in the
  // expansion's order, evaluated left to right. Every term is kept: those with a zero of row 4
  // cannot change a nonzero sum, but they decide the sign of a zero entry (an axis-aligned
  // triangle's), which the file stores.
  const auto cofactor = [&a](const char* const(&terms)[6]) {
    double sum = 0;
    for (int k = 0; k < 6; ++k) {
      const char* f = terms[k];
      const double term =
          a[f[0] - '1'][f[1] - '1'] * a[f[2] - '1'][f[3] - '1'] * a[f[4] - '1'][f[5] - '1'];
      sum = k == 0 ? term : (k < 3 ? sum + term : sum - term);
    }
    return sum;
  };
  static const char* const kAdjugate[3][4][6] = {
      {{"223344", "233442", "243243", "223443", "233244", "243342"},
       {"123443", "133244", "143342", "123344", "133442", "143243"},
       {"122344", "132442", "142243", "122443", "132244", "142342"},
       {"122433", "132234", "142332", "122334", "132432", "142233"}},
      {{"213443", "233144", "243341", "213344", "233441", "243143"},
       {"113344", "133441", "143143", "113443", "133144", "143341"},
       {"112443", "132144", "142341", "112344", "132441", "142143"},
       {"112334", "132431", "142133", "112433", "132134", "142331"}},
      {{"213244", "223441", "243142", "213442", "223144", "243241"},
       {"113442", "123144", "143241", "113244", "123441", "143142"},
       {"112244", "122441", "142142", "112442", "122144", "142241"},
       {"112432", "122134", "142231", "112234", "122431", "142132"}}};
  // The determinant: of its 24 terms only the six without a zero of row 4 remain (the zero terms
  // cannot change a nonzero determinant; a zero one, R1's column in a plane at distance 1, makes
  // the entries infinities and NaNs either way).
  const double det = a[0][0] * a[1][1] * a[2][2] + a[0][1] * a[1][2] * a[2][0] +
                     a[0][2] * a[1][0] * a[2][1] - a[0][0] * a[1][2] * a[2][1] -
                     a[0][1] * a[1][0] * a[2][2] - a[0][2] * a[1][1] * a[2][0];
  const double inverse = 1.0 / det;
  UnitTriangleMatrix out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.m[i][j] = inverse * cofactor(kAdjugate[i][j]);
    out.t[i] = inverse * cofactor(kAdjugate[i][3]);
  }
  return out;
}

UttmWords packUttm(const UnitTriangleMatrix& matrix) {
  std::array<uint32_t, kUttmEntries> fields;
  for (int i = 0; i < 9; ++i)
    fields[i] = truncatedBits(static_cast<float>(matrix.m[i / 3][i % 3]), kFloat24Bits);
  for (int i = 0; i < 3; ++i)
    fields[9 + i] = truncatedBits(static_cast<float>(matrix.t[i]), kFloat24Bits);
  // Four fields of 24 bits fill three words.
  UttmWords words{};
  for (int group = 0; group < 3; ++group) {
    const uint32_t* f = &fields[4 * group];
    uint32_t* w = &words[3 * group];
    w[0] = f[0] << 8 | f[1] >> 16;
    w[1] = f[1] << 16 | f[2] >> 8;
    w[2] = f[2] << 24 | f[3];
  }
  return words;
}

std::array<float, kUttmEntries> unpackUttm(const UttmWords& words) {
  std::array<float, kUttmEntries> entries;
  for (int group = 0; group < 3; ++group) {
    const uint32_t* w = &words[3 * group];
    const uint32_t fields[4] = {w[0] >> 8, (w[0] & 0xFF) << 16 | w[1] >> 16,
                                (w[1] & 0xFFFF) << 8 | w[2] >> 24, w[2] & 0xFFFFFF};
    for (int i = 0; i < 4; ++i) entries[4 * group + i] = paddedFloat(fields[i], kFloat24Bits);
  }
  return entries;
}

}  // namespace rtu
