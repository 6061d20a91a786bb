#pragma once
// One SVO memory for an animated scene: every model's image once, one after another (child
// pointers and far words are relative, so an image moves without change), then one 16-word model
// header per instance, rewritten for each frame as an animation system would update them before
// the RTU fetches them (thesis section 6.2.1).

#include <vector>

#include "scene/model_cache.h"
#include "scene/scene_manager.h"

namespace rtu {

// The sphere around an instance's solid voxels placed in the world: centred on the placed box
// centre, reaching its corners after the anisotropic scale, widened by 1e-3 of its radius so that
// rounding in the job set-up cannot put a voxel just outside it.
BoundingSphere boundingSphere(const VoxelBounds& bounds, const ModelPlacement& placement);

class SceneMemory {
 public:
  // `instanceModels[i]` is the index into `models` of instance i's model.
  SceneMemory(const std::vector<SceneModel>& models, std::vector<size_t> instanceModels);

  // Writes each instance's header for `placements` (one per instance) and returns the instances
  // as the scene manager takes them. Throws std::invalid_argument as makeModelHeader does.
  std::vector<SceneInstance> place(const std::vector<ModelPlacement>& placements);

  // Valid until the next place().
  WordMemory memory() const { return WordMemory(words_); }
  ModelHeaderWords headerWords(size_t instance) const;
  size_t instanceCount() const { return instanceModels_.size(); }
  // Word address of the instance's header: what a ray record against it names.
  uint32_t headerAddress(size_t instance) const {
    return headersStart_ + static_cast<uint32_t>(instance * kModelHeaderWords);
  }

 private:
  std::vector<uint32_t> words_;
  std::vector<uint32_t> modelRoots_;
  std::vector<VoxelBounds> modelBounds_;
  std::vector<size_t> instanceModels_;
  uint32_t headersStart_ = 0;
};

}  // namespace rtu
