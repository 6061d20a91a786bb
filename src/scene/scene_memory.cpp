#include "scene/scene_memory.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace rtu {

BoundingSphere boundingSphere(const VoxelBounds& bounds, const ModelPlacement& placement) {
  const glm::dvec3 centre = 0.5 * (bounds.lower + bounds.upper);
  const glm::dvec3 halfDiagonal = 0.5 * (bounds.upper - bounds.lower) * placement.scale;
  return {placement.rotation * (placement.scale * centre) + placement.translation,
          glm::length(halfDiagonal) * (1.0 + 1e-3)};
}

SceneMemory::SceneMemory(const std::vector<SceneModel>& models, std::vector<size_t> instanceModels)
    : instanceModels_(std::move(instanceModels)) {
  for (const SceneModel& model : models) {
    const std::vector<uint32_t>& image = model.scene.image.words;
    if (words_.size() + image.size() > std::numeric_limits<uint32_t>::max() / 2)
      throw std::invalid_argument("the scene's models do not fit in 32-bit word addresses");
    modelRoots_.push_back(static_cast<uint32_t>(words_.size()) + model.scene.image.root);
    modelBounds_.push_back(model.bounds);
    words_.insert(words_.end(), image.begin(), image.end());
  }
  for (const size_t model : instanceModels_)
    if (model >= models.size())
      throw std::invalid_argument("instance of a model that is not there");
  headersStart_ = static_cast<uint32_t>(words_.size());
  words_.resize(words_.size() + instanceModels_.size() * kModelHeaderWords, 0);
}

std::vector<SceneInstance> SceneMemory::place(const std::vector<ModelPlacement>& placements) {
  if (placements.size() != instanceModels_.size())
    throw std::invalid_argument("one placement per instance expected");
  std::vector<SceneInstance> instances;
  for (size_t i = 0; i < placements.size(); ++i) {
    const size_t model = instanceModels_[i];
    const ModelHeaderWords header =
        encodeModelHeader(makeModelHeader(placements[i], modelRoots_[model]));
    std::copy(header.begin(), header.end(), words_.begin() + headerAddress(i));
    instances.push_back({headerAddress(i), boundingSphere(modelBounds_[model], placements[i])});
  }
  return instances;
}

ModelHeaderWords SceneMemory::headerWords(size_t instance) const {
  ModelHeaderWords header;
  std::copy_n(words_.begin() + headerAddress(instance), kModelHeaderWords, header.begin());
  return header;
}

}  // namespace rtu
