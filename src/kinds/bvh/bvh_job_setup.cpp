#include "kinds/bvh/bvh_job_setup.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_intersectors.h"
#include "kinds/bvh/langr_node.h"

namespace rtu {

BvhJobSetup::Model BvhJobSetup::readModel(uint32_t address) const {
  const ModelHeader header = readModelHeader(memory_, address);
  const std::string where = "model header at word " + std::to_string(address) + ": BVH image at " +
                            std::to_string(header.root);
  // Its sections start on multiples of 4 words from it (bvh_image.h): so do the core's accesses.
  if (header.root % BvhTraversal<LangrNode, SelectedIntersector>::kWordsPerRead != 0)
    throw std::runtime_error(where + " is not on a multiple of 4 words");
  if (memory_.size() - header.root < kBvhHeaderWords)
    throw std::runtime_error(where + " runs past the end of the memory (" +
                             std::to_string(memory_.size()) + " words)");
  std::array<uint32_t, kBvhHeaderWords> words;
  for (uint32_t i = 0; i < kBvhHeaderWords; ++i) words[i] = memory_.read(header.root + i);
  const BvhHeader image = decodeHeader(words.data());
  if (image.magic != kBvhMagic || image.kind != kBvhKind)
    throw std::runtime_error(where + " is not a BVH image (magic " + std::to_string(image.magic) +
                             ", kind " + std::to_string(image.kind) + ")");
  const BvhSections sections = sectionsOf(image);
  return Model{header, BvhSections{header.root + sections.nodes, header.root + sections.refs,
                                   header.root + sections.triangles}};
}

JobSetUp<BvhJob> BvhJobSetup::setUp(const RayRecord& record) {
  JobSetUp<BvhJob> set;
  set.idWord = record.id;
  set.latency = static_cast<uint64_t>(timing_.stages + timing_.rayStages);
  auto model = models_.find(record.modelAddress);
  if (model == models_.end()) {
    model = models_.emplace(record.modelAddress, readModel(record.modelAddress)).first;
    set.headerFetch = 2 * static_cast<uint64_t>(timing_.headerFetchCycles);
    set.latency += set.headerFetch;
  }
  const ModelSpaceRay ray = toModelSpace(record, model->second.transform);
  const Vec3<float> origin(ray.origin[0], ray.origin[1], ray.origin[2]);
  const Vec3<float> direction(ray.direction[0], ray.direction[1], ray.direction[2]);
  set.job = BvhJob{makeBvhRay(origin, direction, 0.0f, INFINITY), model->second.image};
  return set;
}

}  // namespace rtu
