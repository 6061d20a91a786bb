#include "kinds/bvh/two_level_image.h"

#include <algorithm>

#include "kinds/bvh/bvh_image.h"
#include "rtu/model_header.h"

namespace rtu {
namespace {

void padToAccess(std::vector<uint32_t>& words) { words.resize((words.size() + 3) / 4 * 4, 0); }

BvhSections shifted(const BvhSections& sections, size_t base) {
  const auto b = static_cast<uint32_t>(base);
  return BvhSections{sections.nodes + b, sections.refs + b, sections.triangles + b};
}

}  // namespace

TwoLevelImage::TwoLevelImage(const TwoLevelBvh& bvh) {
  for (const MeshBvh& mesh : bvh.meshes()) {
    meshes_.push_back(shifted(mesh.sections, words_.size()));
    meshTriangles_.push_back(BvhImageView(mesh.image.words).header().triangleCount);
    words_.insert(words_.end(), mesh.image.words.begin(), mesh.image.words.end());
    padToAccess(words_);
  }
  meshWords_ = words_.size();
}

void TwoLevelImage::writeFrame(const TwoLevelBvh& bvh) {
  const TopLevel& frame = bvh.topLevel();
  words_.resize(meshWords_);
  const size_t topBase = words_.size();
  words_.insert(words_.end(), frame.image.words.begin(), frame.image.words.end());
  padToAccess(words_);
  top_ = shifted(frame.sections, topBase);
  const size_t instanceBase = words_.size();
  words_[topBase + kBvhInstanceBaseWord] = static_cast<uint32_t>(instanceBase - topBase);
  uint32_t primitiveBase = 0;
  for (size_t i = 0; i < frame.instances.size(); ++i) {
    const uint32_t mesh = frame.instances[i].mesh;
    ModelHeader header;
    static_cast<ModelTransform&>(header) = frame.transforms[i];
    const ModelHeaderWords placement = encodeModelHeader(header);
    words_.insert(words_.end(), placement.begin(), placement.begin() + 15);
    const BvhSections& sections = meshes_[mesh];
    words_.insert(words_.end(),
                  {primitiveBase, sections.nodes, sections.refs, sections.triangles, 0u});
    primitiveBase += meshTriangles_[mesh];
  }
  worldHeader_ = appendModelHeader(words_, ModelPlacement{}, static_cast<uint32_t>(topBase));
  if (words_.size() > UINT32_MAX) throw BvhCapacityError("a two-level image beyond 2^32 - 1 words");
  instances_ = static_cast<uint32_t>(instanceBase);
}

}  // namespace rtu
