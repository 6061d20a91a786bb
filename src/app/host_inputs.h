#pragma once
// Checks of golden's and replay's inputs whose errors name the file at fault: the ray records'
// set-up against the image, and the trees the job or ray records start from.

#include <ostream>
#include <string>
#include <vector>

#include "config/run_config.h"
#include "inputs/host_buffers.h"
#include "kinds/svo/ray_transform.h"
#include "kinds/svo/svo_image.h"
#include "kinds/svo/thesis_records.h"

namespace rtu {

// The job manager's set-up of world-space ray records against the model headers in the image;
// errors name the ray buffer `path`.
std::vector<TValueRecord> jobsFromRayRecords(const SvoImage& image,
                                             const std::vector<RayRecord>& records,
                                             const std::string& path, float epsilon);

// One warning line per skipped record (at most `kShownSkipped`, then their count), naming the
// buffer `path` of kind `what` ("job buffer", "ray buffer").
constexpr size_t kShownSkipped = 5;
void warnSkippedRecords(const std::string& what, const std::string& path,
                        const std::vector<SkippedRecord>& skipped, std::ostream& out);

// checkRootDepths (stack_check.h) on the trees the jobs start from; a malformed tree is an
// error naming the SVO image and the job or ray buffer of `settings` that points into it.
void checkInputTrees(const SvoImage& image, const std::vector<TValueRecord>& jobs, int stackFrames,
                     bool allowOverflow, const RunConfig& settings);
// The same on the records of a job buffer (readJobRecordsSkipping).
void checkInputTrees(const SvoImage& image, const std::vector<HostRecord>& jobRecords,
                     int stackFrames, bool allowOverflow, const RunConfig& settings);

}  // namespace rtu
