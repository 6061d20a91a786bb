#include "kinds/bvh/bvh_job_setup.h"

#include <cmath>

#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_intersectors.h"
#include "kinds/bvh/langr_node.h"
#include "kinds/bvh/two_level_image.h"

namespace rtu {

BvhJobSetup::Model BvhJobSetup::readModel(uint32_t address) const {
  // Its sections start on multiples of 4 words from it (bvh_image.h): so do the core's accesses.
  const ImageEntry entry =
      readImageEntry(memory_, address, BvhTraversal<LangrNode, SelectedIntersector>::kWordsPerRead,
                     kBvhMagic, kBvhKind, "BVH");
  const BvhSections sections = sectionsOf(decodeHeader(entry.header.data()));
  const uint32_t root = entry.model.root;
  const uint32_t instances = entry.header[kBvhInstanceBaseWord];
  return Model{entry.model,
               BvhSections{root + sections.nodes, root + sections.refs, root + sections.triangles},
               instances != 0 ? root + instances : 0};
}

JobSetUp<BvhJob> BvhJobSetup::setUp(const RayRecord& record) {
  JobSetUp<BvhJob> set;
  const Model& model =
      models_.find(record, set, [this](uint32_t address) { return readModel(address); });
  const ModelSpaceRay ray = toModelSpace(record, model.transform);
  const Vec3<float> origin(ray.origin[0], ray.origin[1], ray.origin[2]);
  const Vec3<float> direction(ray.direction[0], ray.direction[1], ray.direction[2]);
  // A ray with a span leaves a surface: it starts kBvhSpanTMin along; an any-hit ray ends at t = 1.
  const bool anyHit = record.span == RaySpan::AnyHit;
  const float tMin = record.span == RaySpan::Line ? 0.0f : kBvhSpanTMin;
  set.job = BvhJob{makeBvhRay(origin, direction, tMin, anyHit ? 1.0f : INFINITY), model.image,
                   anyHit, model.instances};
  return set;
}

}  // namespace rtu
