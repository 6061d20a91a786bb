#include "kinds/svo/job_setup.h"

namespace rtu {

JobSetup::JobSetup(WordMemory memory, const JobManagerConfig& config)
    : memory_(memory), config_(config) {}

JobSetup::SetUp JobSetup::setUp(const HostRecord& record) {
  if (const auto* ray = std::get_if<RayRecord>(&record)) return rayJob(*ray);
  return tValueJob(std::get<TValueRecord>(record));
}

JobSetup::SetUp JobSetup::tValueJob(const TValueRecord& job) const {
  return {job, static_cast<uint64_t>(config_.stages), 0};
}

JobSetup::SetUp JobSetup::rayJob(const RayRecord& ray) {
  SetUp set;
  set.latency = static_cast<uint64_t>(config_.stages + config_.rayStages);
  auto header = headers_.find(ray.modelAddress);
  if (header == headers_.end()) {
    header = headers_.emplace(ray.modelAddress, readModelHeader(memory_, ray.modelAddress)).first;
    set.headerFetch = static_cast<uint64_t>(config_.headerFetchCycles);
    set.latency += set.headerFetch;
  }
  set.job = rayRecordToJob(ray, header->second, config_.epsilon);
  return set;
}

}  // namespace rtu
