#include "kinds/svo/model_header.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include "kinds/svo/ray_setup.h"

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

// The 3x3 inverse rotation as glm stores it (column-major) from the row-major header.
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

}  // namespace

glm::dmat3 rotationFromEulerDegrees(const glm::dvec3& degrees) {
  const glm::dvec3 radians = glm::radians(degrees);
  glm::dmat4 r(1.0);
  r = glm::rotate(r, radians.z, glm::dvec3(0.0, 0.0, 1.0));
  r = glm::rotate(r, radians.y, glm::dvec3(0.0, 1.0, 0.0));
  r = glm::rotate(r, radians.x, glm::dvec3(1.0, 0.0, 0.0));
  return glm::dmat3(r);
}

void ModelHeader::validate() const {
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

ModelHeader makeModelHeader(const ModelPlacement& placement, uint32_t root) {
  ModelHeader header;
  header.root = root;
  const glm::dmat3 inverse = glm::transpose(placement.rotation);
  for (int k = 0; k < 3; ++k) {
    if (!(placement.scale[k] >= kMinScale && placement.scale[k] <= kMaxScale))
      throw std::invalid_argument(std::string("scale ") + kAxes[k] + " is " +
                                  formatNumber(placement.scale[k]) +
                                  ", it must lie within [2^-32, 2^32]");
    header.translation[k] = static_cast<float>(placement.translation[k]);
    header.inverseScale[k] = static_cast<float>(1.0 / placement.scale[k]);
    for (int column = 0; column < 3; ++column)
      header.inverseRotation[k * 3 + column] = static_cast<float>(inverse[column][k]);
  }
  try {
    header.validate();
  } catch (const std::runtime_error& error) {
    throw std::invalid_argument(std::string("model header: ") + error.what());
  }
  return header;
}

ModelHeaderWords encodeModelHeader(const ModelHeader& header) {
  ModelHeaderWords words{};
  for (int k = 0; k < 3; ++k) {
    words[k] = floatBits(header.translation[k]);
    words[12 + k] = floatBits(header.inverseScale[k]);
  }
  for (int i = 0; i < 9; ++i) words[3 + i] = floatBits(header.inverseRotation[i]);
  words[15] = header.root;
  return words;
}

ModelHeader decodeModelHeader(const ModelHeaderWords& words) {
  ModelHeader header;
  for (int k = 0; k < 3; ++k) {
    header.translation[k] = bitsToFloat(words[k]);
    header.inverseScale[k] = bitsToFloat(words[12 + k]);
  }
  for (int i = 0; i < 9; ++i) header.inverseRotation[i] = bitsToFloat(words[3 + i]);
  header.root = words[15];
  return header;
}

ModelHeader readModelHeader(const WordMemory& memory, uint32_t address) {
  const std::string where = "model header at word " + std::to_string(address);
  if (address > memory.size() || memory.size() - address < kModelHeaderWords)
    throw std::runtime_error(where + " runs past the end of the memory (" +
                             std::to_string(memory.size()) + " words)");
  ModelHeaderWords words;
  for (size_t i = 0; i < kModelHeaderWords; ++i)
    words[i] = memory.read(address + static_cast<uint32_t>(i));
  const ModelHeader header = decodeModelHeader(words);
  try {
    header.validate();
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(where + ": " + error.what());
  }
  if (header.root >= memory.size())
    throw std::runtime_error(where + ": root address " + std::to_string(header.root) +
                             " is outside the memory (" + std::to_string(memory.size()) +
                             " words)");
  return header;
}

}  // namespace rtu
