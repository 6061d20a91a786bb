#include "stack_check.h"

#include <iostream>
#include <set>
#include <stdexcept>
#include <string>

#include "svo_validator.h"

namespace rtu {

void checkStackDepth(const SvoImage& image, const std::vector<TraversalJob>& jobs, int stackFrames,
                     bool allowOverflow) {
  std::set<uint32_t> roots;
  for (const TraversalJob& job : jobs) roots.insert(job.root);
  for (uint32_t root : roots) {
    SvoImage tree = image;
    tree.root = root;
    const SvoReport report = validateSvo(tree, SvoLimits{});
    const int needed = report.depth - 1;
    if (needed <= stackFrames) continue;
    const std::string message = "the tree at root " + std::to_string(root) + " has depth " +
                                std::to_string(report.depth) + " and needs " +
                                std::to_string(needed) + " stack frames; " +
                                std::to_string(stackFrames) + " are configured";
    if (!allowOverflow)
      throw std::invalid_argument(message + " (raise --stack-frames, or --allow-stack-overflow "
                                            "to flag the rays that overflow)");
    std::cerr << "rtusim: warning: " << message << ", deeper rays will be flagged\n";
  }
}

}  // namespace rtu
