#pragma once
// A voxel scene as triangles (issue 27, "the procedural scenes as triangles"): every face of a
// solid voxel whose neighbour across it is empty or outside the grid, as two triangles, in the
// root cube [-1,1]^3 the SVO is built over, so the SVO unit and the triangle units trace exactly
// the same surface. Faces wind counter-clockwise seen from outside the solid; vertices are the
// grid's points, shared between faces.

#include <cstdint>

#include "geometry/triangle_mesh.h"
#include "kinds/svo/voxel_source.h"

namespace rtu {

// The deepest grid voxelFaces takes: 2^27 voxels, a 16 MiB occupancy bitmap.
constexpr int kMaxVoxelFaceDepth = 9;

// Throws std::invalid_argument for a source deeper than kMaxVoxelFaceDepth, std::runtime_error
// when its surface needs more than 2^31 triangles.
TriangleMesh voxelFaces(const VoxelSource& source);

}  // namespace rtu
