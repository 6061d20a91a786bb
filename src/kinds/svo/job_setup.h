#pragma once
// What the job manager computes (thesis 6.2.1, appendix C.2), apart from when: a host record
// becomes a traversal job, and the pipeline latency it takes. A t-value record (the thesis
// driver's) passes the `stages` registers as it is; a ray record goes through its model's header,
// read from memory with the first ray against that model and kept for the rest of the run, then
// the ray transform and the t-parameters of eq. 6.6 in `rayStages` more. The SystemC job manager
// (src/sim/ca/job_manager.h) times it; the recurrence run (src/run/analytic_run.h) takes its
// latencies; the float-to-fixed conversion of the t-values follows in either.

#include <cstdint>
#include <map>
#include <variant>

#include "kinds/svo/fixed_point.h"
#include "kinds/svo/model_header.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/ray_transform.h"
#include "kinds/svo/svo_memory.h"
#include "kinds/svo/thesis_records.h"

namespace rtu {

// A host input record: the thesis driver's t-value record, or a world-space ray against a model.
using HostRecord = std::variant<TValueRecord, RayRecord>;

struct JobManagerConfig {
  FixedFormat format;
  FloatConversion conversion = FloatConversion::Rtl;
  int stages = 6;  // the RTL's P_STAGES
  int rayStages = 6;
  int headerFetchCycles = 16;  // one word per cycle
  float epsilon = static_cast<float>(kDefaultDirectionEpsilon);
};

class JobSetup {
 public:
  JobSetup(WordMemory memory, const JobManagerConfig& config);

  struct SetUp {
    TValueRecord job;
    uint64_t latency = 0;      // cycles from acceptance to the pipeline's output, stalls aside
    uint64_t headerFetch = 0;  // cycles after acceptance in which no record is accepted
  };
  // Throws std::runtime_error for a model header that is not valid.
  SetUp setUp(const HostRecord& record);
  const JobManagerConfig& config() const { return config_; }

 private:
  SetUp tValueJob(const TValueRecord& job) const;
  SetUp rayJob(const RayRecord& ray);

  WordMemory memory_;
  JobManagerConfig config_;
  std::map<uint32_t, ModelHeader> headers_;  // by model address
};

}  // namespace rtu
