#pragma once
// The workload every benchmark measures: 1280x720 primary rays of the default camera on the
// procedural scenes named on the command line (all of them when none is), depth 8 unless a
// benchmark says otherwise.

#include <string>
#include <vector>

#include "inputs/camera.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"

namespace rtu {

inline std::vector<std::string> benchScenes(int argc, char** argv) {
  std::vector<std::string> scenes(argv + 1, argv + argc);
  return scenes.empty() ? proceduralSceneNames() : scenes;
}

inline Camera benchCamera() {
  Camera camera;
  camera.width = 1280;
  camera.height = 720;
  return camera;
}

struct BenchFrame {
  SvoBuild build;
  std::vector<TValueRecord> jobs;
};

inline BenchFrame benchFrame(const std::string& scene, int depth = 8) {
  BenchFrame frame{buildSvo(*makeProceduralScene(scene, depth)), {}};
  frame.jobs = makeFrameJobs(benchCamera(), frame.build.image.root);
  return frame;
}

}  // namespace rtu
