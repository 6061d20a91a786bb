#pragma once
// Whether the configured traversal stack can hold the trees a job stream uses.

#include <vector>

#include "scene_loader.h"
#include "svo_image.h"
#include "traversal_job.h"

namespace rtu {

// Throws std::invalid_argument when a tree the jobs use is deeper than `stackFrames` can hold,
// unless overflow is allowed (then it warns on standard error): the RTL's stack has no check, so
// such rays would corrupt it; rtusim ends them as flagged misses.
void checkStackDepth(const SvoImage& image, const std::vector<TraversalJob>& jobs, int stackFrames,
                     bool allowOverflow);

// The same check before a procedural scene or a mesh is built, from its --depth alone: a tree of
// depth d has descriptors down to level d - 1. Scenes read from files are checked once loaded.
void checkBuiltSceneFitsStack(const SceneSpec& scene, int stackFrames, bool allowOverflow);

}  // namespace rtu
