#pragma once
// The models of an animated scene, each built once: a model built from a procedural generator,
// a mesh or a .binvox file is kept in a cache directory as an .svo image named by a hash of its
// description and of its input file's contents, so a changed file or setting builds anew and an
// unchanged one is read back (and validated, like any .svo file) instead of voxelized again.
// .svo models are read as they are.

#include <string>

#include "kinds/svo/scene_loader.h"
#include "kinds/svo/svo_bounds.h"
#include "scene/scene_file.h"

namespace rtu {

struct SceneModel {
  std::string name;
  Scene scene;
  VoxelBounds bounds;  // of its solid voxels, in model space
  bool fromCache = false;
};

// 16 hex digits: FNV-1a over the description (source kind, depth, seed) and the input file.
std::string modelCacheKey(const ModelDescription& model);

// Throws std::runtime_error naming the model for a file that cannot be read or built, and for a
// model without a solid voxel.
SceneModel loadSceneModel(const ModelDescription& model, const std::string& cacheDirectory);

// $XDG_CACHE_HOME/rtusim/models, or ~/.cache/rtusim/models, or ./.rtusim-cache.
std::string defaultModelCacheDirectory();

}  // namespace rtu
