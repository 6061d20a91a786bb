#pragma once
// What makes a triangle mesh unfit for the triangle kinds' builders, found before any long work
// (issue 27: "bad input gets a clear error before long work"). A vertex that is not finite or an
// index past the vertices makes every later box and test meaningless, so it is always an error. A
// degenerate triangle (zero area in double: repeated or collinear vertices) can never be hit by
// the watertight test, and a duplicate (the same three vertex positions in any order as an
// earlier triangle) doubles work and makes the nearest hit a tie between two ids; real scanned
// meshes carry a few of both, so those two may be dropped instead (MeshDefectPolicy::Drop).

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.h"

namespace rtu {

struct MeshDefects {
  std::vector<uint32_t> nonFiniteVertices;  // vertex indices
  std::vector<uint32_t> indexOutOfRange;    // triangle indices
  std::vector<uint32_t> degenerate;         // triangle indices
  std::vector<uint32_t> duplicate;          // triangle indices, each a copy of a lower one

  bool fatal() const { return !nonFiniteVertices.empty() || !indexOutOfRange.empty(); }
  bool droppable() const { return !degenerate.empty() || !duplicate.empty(); }
};

// Every defect of `mesh`. Degenerate and duplicate triangles are looked for only among triangles
// whose indices are in range and whose vertices are finite.
MeshDefects findMeshDefects(const TriangleMesh& mesh);

enum class MeshDefectPolicy { Refuse, Drop };

// The refusal of degenerate or duplicate triangles under MeshDefectPolicy::Refuse: what Drop
// would have removed, so a caller can say how to go on.
class DroppableMeshDefects : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws std::runtime_error naming `source`, the kind of defect, how many and the first indices
// when `mesh` is empty or has a fatal defect, or (policy Refuse: DroppableMeshDefects) a
// degenerate or duplicate triangle; with Drop those are removed and `mesh` keeps the rest in order.
// Returns the dropped triangles' indices in the mesh as given, ascending: the kept triangle k is
// the input's k-th index not among them, which maps a built structure's triangle ids back to the
// file's.
std::vector<uint32_t> checkTriangleMesh(TriangleMesh& mesh, const std::string& source,
                                        MeshDefectPolicy policy);

}  // namespace rtu
