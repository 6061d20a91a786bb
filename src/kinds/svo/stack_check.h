#pragma once
// Whether the configured traversal stack can hold the trees a job stream uses.

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/svo/scene_loader.h"
#include "kinds/svo/svo_image.h"
#include "kinds/svo/thesis_records.h"

namespace rtu {

// One rule for every command that traces an SVO (golden, replay, render on any model, accuracy,
// fps, sweep, fidelity): throws std::invalid_argument, naming `source` (the image's file or the
// scene), when a tree the jobs start from is deeper than `stackFrames` can hold, unless overflow
// is allowed (then it warns on standard error): the RTL's stack has no check, so such rays would
// corrupt it; rtusim ends them as flagged misses. `roots` may repeat.
void checkRootDepths(const SvoImage& image, std::vector<uint32_t> roots, int stackFrames,
                     bool allowOverflow, const std::string& source);
// The same on the stack frames each of `roots` needs (descriptorDepths, svo_validator.h), as
// computed once for a scene that many runs share.
void checkNeededFrames(const std::vector<uint32_t>& roots, const std::vector<int>& needed,
                       int stackFrames, bool allowOverflow, const std::string& source);

// Adds a job's root to those for checkRootDepths unless it repeats the last: a frame's jobs
// mostly share one root, so the roots' sort stays short.
inline void addRoot(std::vector<uint32_t>& roots, uint32_t root) {
  if (roots.empty() || roots.back() != root) roots.push_back(root);
}

// The same check before a procedural scene or a mesh is built, from its --depth alone: a tree of
// depth d has descriptors down to level d - 1. Scenes read from files are checked once loaded.
void checkBuiltSceneFitsStack(const SceneSpec& scene, int stackFrames, bool allowOverflow);

}  // namespace rtu
