#include "kinds/svo/golden_model.h"

namespace rtu {

std::array<int64_t, 3> convertToFixed(const std::array<uint32_t, 3>& floatBits,
                                      const FixedFormat& format, FloatConversion conversion) {
  return {floatToFixed(floatBits[0], format, conversion),
          floatToFixed(floatBits[1], format, conversion),
          floatToFixed(floatBits[2], format, conversion)};
}

GoldenModel::GoldenModel(WordMemory memory, GoldenConfig config)
    : memory_(memory), config_(config), core_(FixedArith{config.format}, config.stackFrames) {
  config_.format.validate();
}

TraversalResult GoldenModel::trace(const TraversalJob& job) {
  core_.start(convertToFixed(job.t0Bits, config_.format, config_.conversion),
              convertToFixed(job.t1Bits, config_.format, config_.conversion), job.a, job.root);
  runToCompletion(core_, memory_);
  core_.finish();
  return makeResult(job.idWord(), core_);
}

std::vector<TraversalResult> GoldenModel::traceAll(const std::vector<TraversalJob>& jobs) {
  std::vector<TraversalResult> results;
  results.reserve(jobs.size());
  for (const TraversalJob& job : jobs) results.push_back(trace(job));
  return results;
}

std::vector<TraversalResult> GoldenModel::traceRays(const std::vector<RayRecord>& records,
                                                    float epsilon) {
  return traceAll(rayRecordsToJobs(memory_, records, epsilon));
}

}  // namespace rtu
