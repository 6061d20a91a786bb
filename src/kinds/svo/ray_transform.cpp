#include "kinds/svo/ray_transform.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace rtu {

namespace {

// Step 4: the magnitude below which a direction component counts as zero.
float zeroThreshold(const std::array<float, 3>& direction, float epsilon) {
  const float largest =
      std::max({std::abs(direction[0]), std::abs(direction[1]), std::abs(direction[2])});
  return std::max(epsilon * largest, std::numeric_limits<float>::min());
}

}  // namespace

TValueRecord rayRecordToJob(const RayRecord& record, const ModelHeader& header, float epsilon) {
  if (!(epsilon > 0.0f && epsilon < 1.0f))
    throw std::invalid_argument("direction epsilon must lie in (0, 1)");
  ModelSpaceRay ray = toModelSpace(record, header);
  std::array<float, 3>& origin = ray.origin;
  std::array<float, 3>& direction = ray.direction;
  const float threshold = zeroThreshold(direction, epsilon);
  TValueRecord job;
  job.id = record.id;
  job.root = header.root;
  job.span = record.span;
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
