#pragma once
// The bounding interval hierarchy of seed 004 (S4 §2.4 p.30 L405-409, §3.4 p.42 L550-552), built
// on the n-bit grid in integers: "only divisions by 2 and comparisons", so the build is exact. The
// seed names only "some heuristic" [WK06] and a leaf below "a certain number" of primitives; the
// plan's reading C13 is WK06's global heuristic:
//   - a candidate box, first the scene's, is split at the middle of its longest axis; each
//     triangle goes left or right by its box's centre;
//   - clip0 = the largest upper bound of the left triangles, clip1 = the smallest lower bound of
//     the right ones (the children's intervals, Fig. 3.5; they may overlap);
//   - when one side is empty no node is emitted: the candidate shrinks to the occupied half and
//     the split is tried again, so both children of a node hold triangles and no leaf has the
//     count 0 that would wrap the FSM's counter (spec 004 §4.4);
//   - a leaf when at most L triangles remain, when the candidate is under one grid unit wide, or
//     at depth kBihMaxDepth.
// Centres and candidates are kept on the half grid (a box's lower + upper bound, in half grid
// units), where the middle ⌊(lo + hi)/2⌋ with the halves [lo, mid] and [mid + 1, hi] shrinks
// every retry; on the grid itself a candidate one unit wide would split into itself. WK07's
// blocks of overlapping triangles are not modelled (C13).

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "kinds/bih/grid.h"
#include "kinds/bih/projected_triangle.h"

namespace rtu {

// The deepest leaf, in edges from the root: a traversal pushes at most once per inner node on its
// path, so its stack never holds more than 31 entries, within the seed's 32 (Listing A.3:
// 5-bit stack_pos, stack at addresses 992-1023).
inline constexpr uint32_t kBihMaxDepth = 31;

struct GridBox {
  GridPoint lower{}, upper{};
};

struct BihBuildSettings {
  uint32_t leafSize = 4;  // L: a node of at most this many triangles is a leaf (C13; >= 1)
};

struct BihBuildNode {
  bool leaf = false;
  uint32_t axis = 0;  // inner: 0, 1, 2 for x, y, z
  // Inner: the left child's upper and the right child's lower bound on `axis`, in grid units.
  int64_t clip0 = 0, clip1 = 0;
  uint32_t index = 0;  // inner: the left child c, the right is c + 1; leaf: its first list entry
  uint32_t count = 0;  // leaf: its triangles (>= 1)
};

struct BihBuild {
  std::vector<BihBuildNode> nodes;  // nodes[0] is the root
  std::vector<uint32_t> list;       // triangle numbers, each leaf's a contiguous range
  uint32_t depth = 0;               // edges from the root to the deepest leaf
};

// The BIH over triangles with grid boxes `boxes` (triangle number i is boxes[i]) in the scene box
// [0, sceneUpper]. Throws std::invalid_argument for no triangles or a leaf size of 0.
BihBuild buildBih(const std::vector<GridBox>& boxes, const GridPoint& sceneUpper,
                  const BihBuildSettings& settings = {});

// The grid box of each projected triangle (in `projected`'s order): its source triangle's vertices
// quantised on `grid`, as the records were made from them.
std::vector<GridBox> triangleBoxes(const TriangleMesh& mesh, const SceneGrid& grid,
                                   const ProjectedMesh& projected);

// The scene box's upper corner on the grid (its lower is 0): the box the traversal starts from
// (C15: the VHDL's aabb constants, per scene).
GridPoint sceneUpper(const SceneGrid& grid);

}  // namespace rtu
