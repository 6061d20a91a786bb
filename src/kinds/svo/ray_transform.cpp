#include "kinds/svo/ray_transform.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

namespace rtu {

namespace {

using Vec3f = std::array<float, 3>;

const char* const kAxes[] = {"x", "y", "z"};

void checkComponents(const Vec3f& v, const std::string& what) {
  for (int k = 0; k < 3; ++k) {
    const std::string field = what + " " + kAxes[k];
    if (!std::isfinite(v[k])) throw std::runtime_error(field + " is not a finite number");
    if (std::abs(v[k]) > kMaxModelCoordinate) throw std::runtime_error(field + " is beyond 2^64");
  }
}

// Row `i` of the row-major matrix times v, accumulated left to right (step 2 and 3).
float rowTimes(const std::array<float, 9>& m, int i, const Vec3f& v) {
  float sum = m[i * 3] * v[0];
  const float second = m[i * 3 + 1] * v[1];
  sum = sum + second;
  const float third = m[i * 3 + 2] * v[2];
  return sum + third;
}

// Steps 1 and 2: the origin in model space.
Vec3f modelOrigin(const Vec3f& origin, const ModelHeader& header) {
  Vec3f v;
  for (int k = 0; k < 3; ++k) v[k] = origin[k] - header.translation[k];
  Vec3f result;
  for (int i = 0; i < 3; ++i)
    result[i] = header.inverseScale[i] * rowTimes(header.inverseRotation, i, v);
  return result;
}

// Step 3: the direction in model space.
Vec3f modelDirection(const Vec3f& direction, const ModelHeader& header) {
  Vec3f result;
  for (int i = 0; i < 3; ++i)
    result[i] = header.inverseScale[i] * rowTimes(header.inverseRotation, i, direction);
  return result;
}

// Step 4: the magnitude below which a direction component counts as zero.
float zeroThreshold(const Vec3f& direction, float epsilon) {
  const float largest =
      std::max({std::abs(direction[0]), std::abs(direction[1]), std::abs(direction[2])});
  return std::max(epsilon * largest, std::numeric_limits<float>::min());
}

}  // namespace

void RayRecord::validate() const {
  if (id > TValueRecord::kMaxId) {
    char word[16];
    std::snprintf(word, sizeof word, "0x%08x", id);
    throw std::runtime_error(std::string("job word ") + word +
                             " has bits 31:28 set (ids have 28 bits)");
  }
  checkComponents(origin, "origin");
  checkComponents(direction, "direction");
  if (direction[0] == 0.0f && direction[1] == 0.0f && direction[2] == 0.0f)
    throw std::runtime_error("direction is zero");
}

RayRecord makeRayRecord(uint32_t id, const Ray& ray, uint32_t modelAddress) {
  const glm::dvec3 direction = glm::normalize(ray.direction);
  RayRecord record;
  record.id = id;
  record.modelAddress = modelAddress;
  for (int k = 0; k < 3; ++k) {
    record.origin[k] = static_cast<float>(ray.origin[k]);
    record.direction[k] = static_cast<float>(direction[k]);
  }
  return record;
}

TValueRecord rayRecordToJob(const RayRecord& record, const ModelHeader& header, float epsilon) {
  if (!(epsilon > 0.0f && epsilon < 1.0f))
    throw std::invalid_argument("direction epsilon must lie in (0, 1)");
  Vec3f origin = modelOrigin(record.origin, header);
  Vec3f direction = modelDirection(record.direction, header);
  const float threshold = zeroThreshold(direction, epsilon);
  TValueRecord job;
  job.id = record.id;
  job.root = header.root;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(direction[k]) < threshold) {
      direction[k] = threshold;
    } else if (direction[k] < 0.0f) {
      direction[k] = -direction[k];
      origin[k] = -origin[k];
      job.a |= static_cast<uint8_t>(1u << k);
    }
    const float r = 1.0f / direction[k];
    const float p = -origin[k] * r;
    job.t0Bits[k] = floatBits(p - r);
    job.t1Bits[k] = floatBits(p + r);
  }
  return job;
}

std::vector<TValueRecord> rayRecordsToJobs(const WordMemory& memory,
                                           const std::vector<RayRecord>& records, float epsilon) {
  std::map<uint32_t, ModelHeader> headers;
  std::vector<TValueRecord> jobs;
  jobs.reserve(records.size());
  for (size_t i = 0; i < records.size(); ++i) {
    const RayRecord& record = records[i];
    try {
      record.validate();
      const uint32_t address = record.modelAddress;
      auto header = headers.find(address);
      if (header == headers.end())
        header = headers.emplace(address, readModelHeader(memory, address)).first;
      jobs.push_back(rayRecordToJob(record, header->second, epsilon));
    } catch (const std::runtime_error& error) {
      throw std::runtime_error("ray record " + std::to_string(i) + ": " + error.what());
    }
  }
  return jobs;
}

}  // namespace rtu
