#pragma once
// What the job manager computes (thesis 6.2.1, appendix C.2), apart from when: a host record
// becomes a traversal job, and the pipeline latency it takes. A t-value record (the thesis
// driver's) passes the `stages` registers as it is; a ray record goes through its model's header,
// read from memory with the first ray against that model and kept for the rest of the run, then
// the ray transform and the t-parameters of eq. 6.6 in `rayStages` more. The SystemC job manager
// (src/sim/ca/job_manager.h) times it; the recurrence run (src/run/analytic_run.h) takes its
// latencies; the float-to-fixed conversion of the t-values follows in either (SvoKind::Setup).

#include <cstdint>
#include <map>

#include "kinds/svo/ray_transform.h"
#include "kinds/svo/svo_memory.h"
#include "kinds/svo/thesis_records.h"
#include "rtu/job_manager_timing.h"
#include "rtu/model_header.h"

namespace rtu {

class JobSetup {
 public:
  // `epsilon`: direction components below it times the largest count as zero (GoldenConfig).
  JobSetup(WordMemory memory, const JobManagerTiming& timing, float epsilon);

  struct SetUp {
    TValueRecord job;
    uint64_t latency = 0;      // cycles from acceptance to the pipeline's output, stalls aside
    uint64_t headerFetch = 0;  // cycles after acceptance in which no record is accepted
  };
  SetUp setUp(const TValueRecord& record) const;
  // Throws std::runtime_error for a model header that is not valid.
  SetUp setUp(const RayRecord& ray);

 private:
  WordMemory memory_;
  JobManagerTiming timing_;
  float epsilon_;
  std::map<uint32_t, ModelHeader> headers_;  // by model address
};

}  // namespace rtu
