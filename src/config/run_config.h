#pragma once
// Everything one run of rtusim is configured by: the simulated RTU and the workload (scene,
// camera, job or ray buffers). Its settings are declared once, in config_schema.cpp; this is
// only their storage.

#include <string>

#include "inputs/camera.h"
#include "inputs/ray_workload.h"
#include "kinds/svo/scene_loader.h"
#include "raypipe/raypipe_camera.h"
#include "raypipe/raypipe_config.h"
#include "run/model_run.h"
#include "run/sampled_run.h"
#include "sim/rtu_config.h"

namespace rtu {

// The acceleration structure `build` makes, and how (issue 27): the thesis' octree, seed 003's
// BVH, seed 004's BIH or seed 001's k-d tree over the scene's triangles.
struct AccelSpec {
  std::string structure = "svo";     // svo | bvh | bih | kdtree
  std::string builder = "binned";    // bvh: langr | binned | sweep | lbvh
  bool dropBadTriangles = false;     // degenerate and duplicate triangles dropped, not refused
  std::string index = "seed";        // bih, kdtree: the seed's index widths, or wide
  std::string kdEdgeOrder = "flat";  // kdtree: edges at equal positions, flat, pbrt or r1
  std::string kdMatrix =
      "normal";      // kdtree: the unit-triangle matrices' third column, normal or r1
  std::string file;  // a built triangle structure's image to trace (.bvh)
};

// What a run models: the thesis' RTU (cores of a kind behind a job manager) or seed 001's ray pipe
// (the Tray Racer, issue 29: docs/raypipe.md).
enum class Architecture : uint8_t { Rtu, Raypipe };

// The ray pipe's workload: its camera registers and the seed's resolution level.
struct RaypipeView {
  RaypipeCameraSettings camera;  // unset registers converted from RunConfig::camera
  int level = -1;                // 0-5, or -1: the camera's width and height
};

struct RunConfig {
  Architecture architecture = Architecture::Rtu;
  RaypipeConfig raypipe;
  RaypipeView raypipeView;
  RtuConfig rtu;
  ModelKind model = ModelKind::CycleAccurate;  // which model answers (replay, render, fps, sweep)
  SceneSpec scene;
  AccelSpec accel;
  Camera camera;
  double epsilon = kDefaultDirectionEpsilon;  // the driver's replacement of zero directions
  std::string jobs, rays;                     // host input buffers of `replay` and `golden`
  // workload.rays: a frame's passes, "primary,shadow,ao" (render, fps, sweep, compare;
  // explore/ray_passes.h), and the other workload.* keys: how the secondary passes spawn their
  // rays (their type is each pass's; the self-intersection offset is the format's, ray_passes.h)
  std::string rayPasses = "primary";
  RayWorkloadSpec workload;
  bool allowStackOverflow = false;
  SampleSpec sample;  // fps and sweep rows
};

}  // namespace rtu
