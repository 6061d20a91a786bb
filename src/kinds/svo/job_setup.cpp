#include "kinds/svo/job_setup.h"

namespace rtu {

JobSetup::JobSetup(WordMemory memory, const JobManagerTiming& timing, float epsilon)
    : memory_(memory), timing_(timing), epsilon_(epsilon) {}

JobSetup::SetUp JobSetup::setUp(const TValueRecord& record) const {
  return {record, static_cast<uint64_t>(timing_.stages), 0};
}

JobSetup::SetUp JobSetup::setUp(const RayRecord& ray) {
  SetUp set;
  set.latency = static_cast<uint64_t>(timing_.stages + timing_.rayStages);
  auto header = headers_.find(ray.modelAddress);
  if (header == headers_.end()) {
    header = headers_.emplace(ray.modelAddress, readModelHeader(memory_, ray.modelAddress)).first;
    set.headerFetch = static_cast<uint64_t>(timing_.headerFetchCycles);
    set.latency += set.headerFetch;
  }
  set.job = rayRecordToJob(ray, header->second, epsilon_);
  return set;
}

}  // namespace rtu
