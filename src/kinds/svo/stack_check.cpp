#include "kinds/svo/stack_check.h"

#include <algorithm>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>

#include "kinds/svo/svo_validator.h"

namespace rtu {

void checkRootDepths(const SvoImage& image, std::vector<uint32_t> roots, int stackFrames,
                     bool allowOverflow, const std::string& source) {
  std::sort(roots.begin(), roots.end());
  roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
  checkNeededFrames(roots, descriptorDepths(image, roots), stackFrames, allowOverflow, source);
}

void checkNeededFrames(const std::vector<uint32_t>& roots, const std::vector<int>& needed,
                       int stackFrames, bool allowOverflow, const std::string& source) {
  size_t deepest = 0;
  size_t tooDeep = 0;
  for (size_t i = 0; i < roots.size(); ++i) {
    tooDeep += needed[i] > stackFrames;
    if (needed[i] > needed[deepest]) deepest = i;
  }
  if (tooDeep == 0) return;
  std::string message = source + ": the tree at root " + std::to_string(roots[deepest]) +
                        " has descriptors at depth " + std::to_string(needed[deepest]) +
                        " and needs " + std::to_string(needed[deepest]) + " stack frames; " +
                        std::to_string(stackFrames) + " are configured";
  if (tooDeep > 1)
    message += " (" + std::to_string(tooDeep) + " of the " + std::to_string(roots.size()) +
               " trees the jobs use are too deep)";
  if (!allowOverflow)
    throw std::invalid_argument(message + " (raise --stack-frames, or --allow-stack-overflow "
                                          "to flag the rays that overflow)");
  std::cerr << "rtusim: warning: " << message << ", deeper rays will be flagged\n";
}

void checkBuiltSceneFitsStack(const SceneSpec& scene, int stackFrames, bool allowOverflow) {
  const bool built = scene.svoFile.empty() && scene.binvoxFile.empty();
  const int needed = scene.depth - 1;
  if (!built || allowOverflow || needed <= stackFrames) return;
  throw std::invalid_argument("--depth " + std::to_string(scene.depth) +
                              " builds descriptors down to level " + std::to_string(needed) +
                              ", which needs " + std::to_string(needed) + " stack frames; " +
                              std::to_string(stackFrames) +
                              " are configured (raise --stack-frames, lower --depth, or "
                              "--allow-stack-overflow to flag the rays that overflow)");
}

}  // namespace rtu
