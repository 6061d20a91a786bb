#include "kinds/svo/golden_model.h"

namespace rtu {

GoldenModel::GoldenModel(WordMemory memory, GoldenConfig config)
    : config_(config), shell_(memory, config) {
  config_.format.validate();
}

TraversalResult GoldenModel::trace(const TValueRecord& job) {
  TraversalResult result;
  shell_.run(job.idWord(), SvoKind::setUp(job, config_), result);
  return result;
}

std::vector<TraversalResult> GoldenModel::traceAll(const std::vector<TValueRecord>& jobs) {
  std::vector<TraversalResult> results;
  results.reserve(jobs.size());
  for (const TValueRecord& job : jobs) results.push_back(trace(job));
  return results;
}

std::vector<TraversalResult> GoldenModel::traceRays(const std::vector<RayRecord>& records,
                                                    float epsilon) {
  return traceAll(rayRecordsToJobs(shell_.memory(), records, epsilon));
}

}  // namespace rtu
