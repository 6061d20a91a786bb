#include "app/host_inputs.h"

#include <stdexcept>
#include <utility>
#include <variant>

#include "kinds/svo/stack_check.h"
#include "kinds/svo/svo_validator.h"

namespace rtu {

namespace {

// checkRootDepths; a malformed tree is an error naming the SVO image and the job or ray buffer.
void checkRootTrees(const SvoImage& image, std::vector<uint32_t> roots, int stackFrames,
                    bool allowOverflow, const RunConfig& settings) {
  try {
    checkRootDepths(image, std::move(roots), stackFrames, allowOverflow,
                    "SVO image '" + settings.scene.svoFile + "'");
  } catch (const SvoFormatError& error) {
    // The tree is broken, or a record's root points outside it: either file may be at fault.
    const std::string records = settings.rays.empty() ? "job buffer '" + settings.jobs + "'"
                                                      : "ray buffer '" + settings.rays + "'";
    throw std::runtime_error("SVO image '" + settings.scene.svoFile + "' with the roots of the " +
                             records + ": " + error.what());
  }
}

}  // namespace

std::vector<TValueRecord> jobsFromRayRecords(const SvoImage& image,
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

void checkInputTrees(const SvoImage& image, const std::vector<TValueRecord>& jobs, int stackFrames,
                     bool allowOverflow, const RunConfig& settings) {
  std::vector<uint32_t> roots;
  for (const TValueRecord& job : jobs) addRoot(roots, job.root);
  checkRootTrees(image, std::move(roots), stackFrames, allowOverflow, settings);
}

void checkInputTrees(const SvoImage& image, const std::vector<HostRecord>& jobRecords,
                     int stackFrames, bool allowOverflow, const RunConfig& settings) {
  std::vector<uint32_t> roots;
  for (const HostRecord& record : jobRecords) addRoot(roots, std::get<TValueRecord>(record).root);
  checkRootTrees(image, std::move(roots), stackFrames, allowOverflow, settings);
}

}  // namespace rtu
