#pragma once
// Everything one run of rtusim is configured by: the simulated RTU and the workload (scene,
// camera, job or ray buffers). Its settings are declared once, in config_schema.cpp; this is
// only their storage.

#include <string>

#include "inputs/camera.h"
#include "kinds/svo/scene_loader.h"
#include "run/model_run.h"
#include "run/sampled_run.h"
#include "sim/rtu_config.h"

namespace rtu {

struct RunConfig {
  RtuConfig rtu;
  ModelKind model = ModelKind::CycleAccurate;  // which model answers (replay, render, fps, sweep)
  SceneSpec scene;
  Camera camera;
  double epsilon = kDefaultDirectionEpsilon;  // the driver's replacement of zero directions
  std::string jobs, rays;                     // host input buffers of `replay` and `golden`
  bool allowStackOverflow = false;
  SampleSpec sample;  // fps and sweep rows
};

}  // namespace rtu
