#include "scene/hit_buffer.h"

#include <stdexcept>
#include <utility>

namespace rtu {

HitBuffer::HitBuffer(size_t pixels) : hits_(pixels), stored_(pixels, 0) {}

void HitBuffer::beginFrame(bool cameraMoved, std::vector<uint8_t> instanceMoved) {
  if (!instanceMoved_.empty() && instanceMoved.size() != instanceMoved_.size())
    throw std::invalid_argument("hit buffer: the number of instances changed between frames");
  cameraMoved_ = cameraMoved;
  instanceMoved_ = std::move(instanceMoved);
}

bool HitBuffer::crossesMovedInstance(const RayRecord& ray,
                                     const std::vector<SceneInstance>& instances) const {
  for (size_t i = 0; i < instances.size(); ++i)
    if (instanceMoved_[i] && raySphereSpan(ray, instances[i].sphere).crosses) return true;
  return false;
}

const SceneHit* HitBuffer::reusable(size_t pixel, const RayRecord& ray,
                                    const std::vector<SceneInstance>& instances) const {
  if (cameraMoved_ || !stored_[pixel]) return nullptr;
  const SceneHit& last = hits_[pixel];
  if (last.instance >= 0 && instanceMoved_[static_cast<size_t>(last.instance)]) return nullptr;
  if (crossesMovedInstance(ray, instances)) return nullptr;
  return &last;
}

void HitBuffer::store(size_t pixel, const SceneHit& hit) {
  hits_[pixel] = hit;
  stored_[pixel] = 1;
}

}  // namespace rtu
