#pragma once
// A small scene for the scene manager's tests: three balls of two models, overlapping on screen
// and in depth, one rotated and squashed, so that a frame has rays culled against every
// instance, rays through several instances and rays that end early.

#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "inputs/camera.h"
#include "kinds/svo/svo_builder.h"
#include "scene/scene_manager.h"
#include "scene/scene_memory.h"

namespace rtu {

// A sphere of radius 0.8 voxelized at `depth`.
class BallSource : public VoxelSource {
 public:
  explicit BallSource(int depth) : depth_(depth) {}
  int depth() const override { return depth_; }
  Occupancy classify(const OctreeNode& node) const override {
    if (node.level < depth_) return Occupancy::Mixed;
    return glm::length(node.centre()) <= 0.8 ? Occupancy::Full : Occupancy::Empty;
  }

 private:
  int depth_;
};

inline SceneModel ballModel(int depth) {
  SceneModel model;
  model.scene.image = buildSvo(BallSource(depth)).image;
  model.bounds = solidVoxelBounds(model.scene.image);
  return model;
}

// Three balls overlapping on screen and in depth, one of them rotated and squashed.
struct ThreeBalls {
  SceneMemory memory{{ballModel(4), ballModel(5)}, {0, 1, 0}};
  std::vector<SceneInstance> instances;

  ThreeBalls() {
    std::vector<ModelPlacement> placements(3);
    placements[0].translation = {-0.4, 0.0, 0.0};
    placements[1].translation = {0.5, 0.2, 1.2};
    placements[2].translation = {0.0, -0.3, 2.6};
    placements[2].scale = {1.4, 0.7, 1.0};
    placements[2].rotation = glm::mat3_cast(glm::angleAxis(0.6, glm::dvec3(0, 0, 1)));
    instances = memory.place(placements);
  }
};

inline std::vector<RayRecord> frameRays(int width, int height) {
  Camera camera;
  camera.position = {0.3, 0.4, -3.5};
  camera.lookAt = {0.0, 0.0, 1.0};
  camera.width = width;
  camera.height = height;
  std::vector<RayRecord> rays;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      rays.push_back(
          makeRayRecord(static_cast<uint32_t>(x + y * width), camera.primaryRay(x, y), 0));
  return rays;
}

}  // namespace rtu
