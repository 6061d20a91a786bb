#pragma once
// The hit buffer object of thesis section 4.3.4: each pixel's scene-manager answer of the last
// frame, reused when it cannot have changed.
//
// The thesis reuses a pixel when the camera and the instance it hit are unchanged and the ray
// crossed no other bounding sphere before the hit. This buffer asks for less and is still exact:
// the camera is unchanged (so the ray is the same, bit for bit), the instance hit is unchanged
// (same header, so the same job and result), and the ray crosses the bounding sphere of no
// instance that moved. Instances that did not move gave the same answers as last frame, and a
// moved instance the ray does not reach cannot hide the hit or make a miss a hit. A miss is
// reused on the same terms.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/scene_manager.h"

namespace rtu {

class HitBuffer {
 public:
  explicit HitBuffer(size_t pixels);

  // Starts a frame: whether the camera moved, and per instance whether its header changed since
  // the last frame. The instance list must keep its length from frame to frame.
  void beginFrame(bool cameraMoved, std::vector<uint8_t> instanceMoved);

  // The last frame's answer for `pixel` when it still holds for `ray`, else nullptr.
  const SceneHit* reusable(size_t pixel, const RayRecord& ray,
                           const std::vector<SceneInstance>& instances) const;
  // Safe from several threads for distinct pixels.
  void store(size_t pixel, const SceneHit& hit);

 private:
  bool crossesMovedInstance(const RayRecord& ray,
                            const std::vector<SceneInstance>& instances) const;

  std::vector<SceneHit> hits_;
  std::vector<uint8_t> stored_;  // bytes, not vector<bool>: threads write distinct pixels
  bool cameraMoved_ = true;
  std::vector<uint8_t> instanceMoved_;
};

}  // namespace rtu
