#pragma once
// `rtusim precision --triangles`: the triangle formats' study (explore/triangle_precision.h) run
// on a scene's triangles and on seed 004's stress triangle, printed as a table and written as CSV.

#include <string>

#include "config/run_config.h"
#include "explore/triangle_precision.h"

namespace rtu {

struct TrianglePrecisionOptions {
  TriangleSweep sweep{
      {12, 16, 20, 24}, {12, 16, 20, 24}, {4, 6, 8, 12}, {8, 16, 24}, {0, 4, 8, 12}};
  TriangleRaySettings rays;
  int stressWidth = 640;  // S4 §2.5.1's 640x480 image, height 3/4 of it; 0 skips the stress rows
  bool dropBadTriangles = false;  // the mesh's degenerate and duplicate triangles dropped
  std::string csv;
};

// Throws std::invalid_argument naming the flag for a format out of range or a ray count below 1,
// before any tracing.
// The scene's triangles come from `settings` (--mesh or a voxel scene's faces).
void runTrianglePrecision(const TrianglePrecisionOptions& options, RunConfig settings);

// A figure as both precision reports print it: four significant digits (%.4g).
std::string precisionFigure(double value);

}  // namespace rtu
