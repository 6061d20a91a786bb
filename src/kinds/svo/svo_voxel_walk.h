#pragma once
// An independent geometric oracle for SVO traversal (issue 26): the first leaf voxel a ray meets,
// found by geometry alone, in float64, sharing no code with the traversal core.
//
// Every equivalence test runs TraversalCore (golden, cycle-accurate, loosely-timed and the
// per-cycle reference alike), so a control-flow bug in it would pass them all. This walk does not
// use the thesis algorithm (no t-midpoints, no child-order tables, no mirroring, no stack): it
// locates the point where the ray currently is by descending the octree from the root (point
// location, decoding the descriptors itself), takes the slab test of the cell found, and moves to
// the point where the ray leaves that cell, until the cell is a leaf voxel or the ray leaves the
// root cube [-1,1]^3. It reads the image only through WordMemory and Descriptor's field accessors
// (the word format) and counts the siblings before a child itself. It must not include
// traversal_core.h, reference_model.h, golden_model.h or ray_setup.h.

#include <array>
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

#include "kinds/svo/svo_memory.h"

namespace rtu {

struct VoxelWalkOptions {
  // How far, in t, the model under test may place a plane crossing of each axis from the exact
  // one (0 for an exact comparison). Only used for the clearance below.
  std::array<double, 3> tUncertainty{};
  // Deepest level the walk descends to; a deeper image (or a cycle of child pointers) throws.
  int maxLevel = 30;
  // Cells the walk may visit before it throws (a guard against a walk that makes no progress).
  long maxCells = 1L << 22;
};

struct VoxelWalkResult {
  bool hit = false;
  // Where the line enters the hit voxel's box: the largest of its three near-face t-values, with
  // p(t) = origin + t * direction. Like the traversal core, the walk starts where the line enters
  // the root cube, which may be behind the origin (t < 0).
  double tHit = 0.0;
  int entryAxis = 0;  // the axis of that face (ties go to x, then y, as the hardware's)
  // The hit voxel as a cell of the 2^level grid over [-1,1]^3 (src/kinds/svo/voxel_source.h's
  // OctreeNode convention: cell x spans [-1 + x * 2 / 2^level, -1 + (x + 1) * 2 / 2^level]).
  int level = 0;
  uint32_t x = 0, y = 0, z = 0;
  // The hit voxel named as TraversalCore::hitVoxel names it: the word address of its parent's
  // descriptor, shifted left by 3, or'ed with its slot. Lets a test check "the same voxel".
  uint64_t voxelKey = 0;
  // The smallest margin, in t, of any decision the walk took: at every cell it entered, how far
  // (|d_k| scaled) the entry point was from the cell's faces on the other axes, and at every cell
  // it left, how much later the other axes' exit planes came; each gap less the two axes'
  // tUncertainty. Also the root cube: how far apart the entry and exit planes were. A model whose
  // t-values are each within tUncertainty of the exact ones takes every decision of this walk the
  // same way when clearance > 0; when it is <= 0 the ray grazes an edge of the voxel grid within
  // that uncertainty, and a different answer is explained. Infinite when no decision was taken.
  double clearance = std::numeric_limits<double>::infinity();
  long cells = 0;        // cells located: the empty ones passed and the leaf hit
  long farPointers = 0;  // far words read while locating them
};

// Walks the line p(t) = origin + t * direction (any non-zero direction, not necessarily unit
// length; a zero component means the line is parallel to those planes) through the SVO whose
// root descriptor is at word `root` of `memory`. Throws std::invalid_argument for a non-finite or
// zero direction, std::runtime_error for an image deeper than options.maxLevel or a walk longer
// than options.maxCells.
VoxelWalkResult walkVoxels(const WordMemory& memory, uint32_t root, const glm::dvec3& origin,
                           const glm::dvec3& direction, const VoxelWalkOptions& options = {});

// The line a traversal job describes, so that t means what the golden model's tHit means: the
// direction normalised, then each exactly zero component replaced by `epsilon` (not normalised
// again), as the job set-up does (thesis 4.1.3). Written here again on purpose: the oracle
// includes none of the set-up code.
glm::dvec3 jobLineDirection(const glm::dvec3& direction, double epsilon);

}  // namespace rtu
