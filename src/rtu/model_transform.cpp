#include "rtu/model_transform.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

namespace rtu {

namespace {

constexpr double kRotationTolerance = 1e-5;
constexpr double kMinScale = 1.0 / kMaxInverseScale;
constexpr double kMaxScale = 1.0 / kMinInverseScale;
const char* const kAxes[] = {"x", "y", "z"};

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

void checkFinite(float value, const std::string& field) {
  if (!std::isfinite(value)) throw std::runtime_error(field + " is not a finite number");
}

// The 3x3 inverse rotation as glm stores it (column-major) from the row-major transform.
glm::dmat3 inverseRotationMatrix(const std::array<float, 9>& rowMajor) {
  glm::dmat3 m;
  for (int row = 0; row < 3; ++row)
    for (int column = 0; column < 3; ++column) m[column][row] = rowMajor[row * 3 + column];
  return m;
}

void checkRotation(const std::array<float, 9>& rowMajor) {
  const glm::dmat3 m = inverseRotationMatrix(rowMajor);
  const glm::dmat3 product = glm::transpose(m) * m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(product[i][j] - (i == j ? 1.0 : 0.0)) > kRotationTolerance)
        throw std::runtime_error("inverse rotation is not orthonormal");
  if (glm::determinant(m) <= 0.0)
    throw std::runtime_error("inverse rotation is a reflection (determinant < 0), not a rotation");
}

// Row `i` of the row-major matrix times v, accumulated left to right (steps 2 and 3).
float rowTimes(const std::array<float, 9>& m, int i, const std::array<float, 3>& v) {
  float sum = m[i * 3] * v[0];
  const float second = m[i * 3 + 1] * v[1];
  sum = sum + second;
  const float third = m[i * 3 + 2] * v[2];
  return sum + third;
}

}  // namespace

glm::dmat3 rotationFromEulerDegrees(const glm::dvec3& degrees) {
  const glm::dvec3 radians = glm::radians(degrees);
  glm::dmat4 r(1.0);
  r = glm::rotate(r, radians.z, glm::dvec3(0.0, 0.0, 1.0));
  r = glm::rotate(r, radians.y, glm::dvec3(0.0, 1.0, 0.0));
  r = glm::rotate(r, radians.x, glm::dvec3(1.0, 0.0, 0.0));
  return glm::dmat3(r);
}

void ModelTransform::validate() const {
  for (int k = 0; k < 3; ++k) {
    const std::string axis = kAxes[k];
    checkFinite(translation[k], "translation " + axis);
    if (std::abs(translation[k]) > kMaxModelCoordinate)
      throw std::runtime_error("translation " + axis + " is beyond 2^64");
    checkFinite(inverseScale[k], "inverse scale " + axis);
    if (!(inverseScale[k] >= kMinInverseScale && inverseScale[k] <= kMaxInverseScale))
      throw std::runtime_error("inverse scale " + axis + " is " + formatNumber(inverseScale[k]) +
                               ", outside [2^-32, 2^32]");
  }
  for (int i = 0; i < 9; ++i)
    checkFinite(inverseRotation[i], "inverse rotation element " + std::to_string(i));
  checkRotation(inverseRotation);
}

ModelTransform makeModelTransform(const ModelPlacement& placement) {
  ModelTransform transform;
  const glm::dmat3 inverse = glm::transpose(placement.rotation);
  for (int k = 0; k < 3; ++k) {
    if (!(placement.scale[k] >= kMinScale && placement.scale[k] <= kMaxScale))
      throw std::invalid_argument(std::string("scale ") + kAxes[k] + " is " +
                                  formatNumber(placement.scale[k]) +
                                  ", it must lie within [2^-32, 2^32]");
    transform.translation[k] = static_cast<float>(placement.translation[k]);
    transform.inverseScale[k] = static_cast<float>(1.0 / placement.scale[k]);
    for (int column = 0; column < 3; ++column)
      transform.inverseRotation[k * 3 + column] = static_cast<float>(inverse[column][k]);
  }
  try {
    transform.validate();
  } catch (const std::runtime_error& error) {
    throw std::invalid_argument(std::string("model transform: ") + error.what());
  }
  return transform;
}

ModelSpaceRay toModelSpace(const RayRecord& record, const ModelTransform& transform) {
  ModelSpaceRay ray;
  std::array<float, 3> v;
  for (int k = 0; k < 3; ++k) v[k] = record.origin[k] - transform.translation[k];
  for (int i = 0; i < 3; ++i) {
    ray.origin[i] = transform.inverseScale[i] * rowTimes(transform.inverseRotation, i, v);
    ray.direction[i] =
        transform.inverseScale[i] * rowTimes(transform.inverseRotation, i, record.direction);
  }
  return ray;
}

}  // namespace rtu
