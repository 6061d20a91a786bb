#include "kinds/kd/kd_job_setup.h"

#include "rtu/model_transform.h"

namespace rtu {

KdJobSetup::Model KdJobSetup::readModel(uint32_t address) const {
  // Word 1 of a k-d header is its version, which names the layout as a kind word does.
  const ImageEntry entry =
      readImageEntry(memory_, address, KdTraversal::kWordsPerRead, kKdMagic, kKdVersion, "k-d");
  KdSections sections = sectionsOf(decodeKdHeader(entry.header.data()));
  const uint32_t root = entry.model.root;
  sections.nodes += root;
  sections.lists += root;
  sections.uttms += root;
  return Model{entry.model, sections};
}

JobSetUp<KdJob> KdJobSetup::setUp(const RayRecord& record) {
  JobSetUp<KdJob> set;
  const Model& model =
      models_.find(record, set, [this](uint32_t address) { return readModel(address); });
  const ModelSpaceRay ray = toModelSpace(record, model.transform);
  // Hardware space: x and y swapped (trayracer_scene.h, toHardwareSpace).
  const auto swapped = [](const std::array<float, 3>& v) {
    return std::array<float, 3>{v[1], v[0], v[2]};
  };
  // An any-hit ray is the seed's shadow ray: t in [EPSILON, 1], ended at its first hit.
  const bool anyHit = record.span == RaySpan::AnyHit;
  set.job = KdJob{KdRay{swapped(ray.origin), swapped(ray.direction), anyHit}, model.image};
  return set;
}

}  // namespace rtu
