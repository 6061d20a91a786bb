#include "kinds/bvh/two_level.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "kinds/bvh/build_primitives.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/sah_builder.h"

namespace rtu {
namespace {

ModelTransform instanceTransform(const BvhInstance& instance, size_t index, size_t meshes) {
  const std::string name = "two-level BVH: instance " + std::to_string(index);
  if (instance.mesh >= meshes)
    throw std::invalid_argument(name + " names mesh " + std::to_string(instance.mesh) + " of " +
                                std::to_string(meshes));
  try {
    return makeModelTransform(instance.placement);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(name + ": " + error.what());
  }
}

}  // namespace

MeshBvh meshBvh(const BuildTree& tree, const TriangleMesh& mesh) {
  return meshBvh(layOut(tree, mesh));
}

MeshBvh meshBvh(BvhImage image) {
  MeshBvh bvh;
  bvh.image = std::move(image);
  const BvhImageView view(bvh.image.words);
  bvh.sections = sectionsOf(view.header());
  bvh.rootBox = view.node(0).box;
  return bvh;
}

Aabb<double> placedBox(const Aabb<float>& box, const ModelPlacement& placement) {
  Aabb<double> placed;
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec3 c;
    for (int k = 0; k < 3; ++k) c[k] = (corner >> k & 1) ? box.upper[k] : box.lower[k];
    placed.grow(placement.rotation * (placement.scale * c) + placement.translation);
  }
  return placed;
}

TwoLevelBvh::TwoLevelBvh(std::vector<MeshBvh> meshes, const TopLevelConfig& config)
    : meshes_(std::make_shared<const std::vector<MeshBvh>>(std::move(meshes))), config_(config) {
  if (meshes_->empty()) throw std::invalid_argument("two-level BVH: no mesh");
  if (config_.leafSize < 1)
    throw std::invalid_argument("two-level BVH: the top level's leaf size must be at least 1");
}

void TwoLevelBvh::place(std::vector<BvhInstance> instances) {
  if (instances.empty()) throw std::invalid_argument("two-level BVH: no instance to place");
  TopLevel top;
  for (size_t i = 0; i < instances.size(); ++i) {
    top.transforms.push_back(instanceTransform(instances[i], i, meshes_->size()));
    top.worldBoxes.push_back(
        placedBox((*meshes_)[instances[i].mesh].rootBox, instances[i].placement));
  }
  top.instances = std::move(instances);
  top.tree = buildTopLevel(top.worldBoxes);
  top.image = layOutNodes(top.tree, 0);
  top.sections = sectionsOf(BvhImageView(top.image.words).header());
  topLevel_ = std::move(top);
}

BuildTree TwoLevelBvh::buildTopLevel(const std::vector<Aabb<double>>& worldBoxes) const {
  const BuildPrimitives primitives = boxPrimitives(worldBoxes);
  if (config_.builder == TopLevelBuilder::Langr) {
    LangrConfig langr;
    langr.leafThreshold = config_.leafSize;
    return buildLangr(primitives, langr).tree;
  }
  SahBuilderConfig binned;
  binned.maxLeafSize = config_.leafSize;
  return buildSah(primitives, binned).tree;
}

}  // namespace rtu
