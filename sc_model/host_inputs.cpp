#include "host_inputs.h"

#include <stdexcept>

#include "stack_check.h"
#include "svo_validator.h"

namespace rtu {

std::vector<TraversalJob> jobsFromRayRecords(const SvoImage& image,
                                             const std::vector<RayRecord>& records,
                                             const std::string& path, float epsilon) {
  try {
    return rayRecordsToJobs(image.memory(), records, epsilon);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("ray buffer '" + path + "': " + error.what());
  }
}

void warnSkippedRecords(const std::string& what, const std::string& path,
                        const std::vector<SkippedRecord>& skipped, std::ostream& out) {
  for (size_t i = 0; i < skipped.size() && i < kShownSkipped; ++i)
    out << "WARNING     " << what << " '" << path << "': " << skipped[i].problem
        << "; skipped, no result\n";
  if (skipped.size() > kShownSkipped)
    out << "WARNING     " << what << " '" << path << "': " << skipped.size() - kShownSkipped
        << " more records skipped (" << skipped.size() << " in all)\n";
}

void checkInputTrees(const SvoImage& image, const std::vector<TraversalJob>& jobs,
                     int stackFrames, bool allowOverflow, const RunConfig& settings) {
  try {
    checkStackDepth(image, jobs, stackFrames, allowOverflow);
  } catch (const SvoFormatError& error) {
    // The tree is broken, or a record's root points outside it: either file may be at fault.
    const std::string records = settings.rays.empty() ? "job buffer '" + settings.jobs + "'"
                                                      : "ray buffer '" + settings.rays + "'";
    throw std::runtime_error("SVO image '" + settings.scene.svoFile + "' with the roots of the " +
                             records + ": " + error.what());
  }
}

}  // namespace rtu
