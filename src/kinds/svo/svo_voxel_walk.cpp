#include "kinds/svo/svo_voxel_walk.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rtu {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A cell of the 2^level grid over [-1,1]^3, and what the image says it is.
struct Cell {
  int level = 0;
  std::array<uint32_t, 3> index{};
  bool leaf = false;      // a solid voxel; otherwise an empty cell
  uint64_t voxelKey = 0;  // parent descriptor address << 3 | slot

  double size() const { return std::ldexp(2.0, -level); }
  double lower(int k) const { return -1.0 + index[k] * size(); }
  double upper(int k) const { return -1.0 + (index[k] + 1.0) * size(); }
};

// The cell holding point p, from the root down. A coordinate on a splitting plane belongs to the
// side the ray is heading to (the upper one when it runs along the plane), so the point where the
// ray leaves a cell locates the cell it enters next.
Cell locate(const WordMemory& memory, uint32_t root, const glm::dvec3& p, const glm::dvec3& d,
            int maxLevel, long& farPointers) {
  uint32_t address = root;
  Cell cell;
  for (;;) {
    if (cell.level >= maxLevel)
      throw std::runtime_error("voxel walk: the SVO has valid children below level " +
                               std::to_string(maxLevel) + " (descriptor at word " +
                               std::to_string(address) + "; a cycle of child pointers?)");
    // Split the current cell (the root cube at level 0) at its centre.
    const double half = cell.size() * 0.5;
    int slot = 0;
    for (int k = 0; k < 3; ++k) {
      const double middle = cell.lower(k) + half;
      const bool upper = p[k] > middle || (p[k] == middle && d[k] >= 0.0);
      slot |= static_cast<int>(upper) << k;
      cell.index[k] = 2 * cell.index[k] + static_cast<uint32_t>(upper);
    }
    ++cell.level;
    const Descriptor descriptor{memory.read(address)};
    if (!(descriptor.validMask() >> slot & 1)) return cell;  // empty
    if (descriptor.leafMask() >> slot & 1) {
      cell.leaf = true;
      cell.voxelKey = uint64_t{address} << 3 | static_cast<uint64_t>(slot);
      return cell;
    }
    // A valid non-leaf child: the descriptors of the valid non-leaf children are stored in slot
    // order from the descriptor's address plus the child pointer, or plus the word the far
    // pointer names (addresses wrap modulo 2^32).
    uint32_t first = address + descriptor.childPointer();
    if (descriptor.far()) {
      first = address + memory.read(first);
      ++farPointers;
    }
    uint32_t before = 0;
    for (int s = 0; s < slot; ++s)
      before += (descriptor.validMask() >> s & 1) && !(descriptor.leafMask() >> s & 1);
    address = first + before;
  }
}

// The smallest margin of the walk's decisions (VoxelWalkResult::clearance).
struct Clearance {
  std::array<double, 3> uncertainty;
  double value = kInfinity;

  // Two plane crossings, on axes j and k, `gap` apart in t.
  void decide(double gap, int j, int k) {
    value = std::min(value, std::abs(gap) - uncertainty[j] - uncertainty[k]);
  }
};

// t where the line crosses the plane x_k = c; d[k] is not 0.
double crossing(const glm::dvec3& o, const glm::dvec3& d, int k, double c) {
  return (c - o[k]) / d[k];
}

}  // namespace

glm::dvec3 jobLineDirection(const glm::dvec3& direction, double epsilon) {
  const double length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                  direction[2] * direction[2]);
  glm::dvec3 line = direction / length;
  for (int k = 0; k < 3; ++k)
    if (line[k] == 0.0) line[k] = epsilon;
  return line;
}

VoxelWalkResult walkVoxels(const WordMemory& memory, uint32_t root, const glm::dvec3& o,
                           const glm::dvec3& d, const VoxelWalkOptions& options) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(o[k]) || !std::isfinite(d[k]))
      throw std::invalid_argument("voxel walk: origin and direction must be finite");
  if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
    throw std::invalid_argument("voxel walk: the direction is zero");

  VoxelWalkResult result;
  Clearance clearance{options.tUncertainty};

  // The root cube's slab test: the line is inside on every axis between its near and far planes.
  std::array<double, 3> nearT{}, farT{};
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0.0) {
      const bool inside = o[k] >= -1.0 && o[k] <= 1.0;
      nearT[k] = inside ? -kInfinity : kInfinity;
      farT[k] = inside ? kInfinity : -kInfinity;
    } else {
      nearT[k] = crossing(o, d, k, d[k] > 0 ? -1.0 : 1.0);
      farT[k] = crossing(o, d, k, d[k] > 0 ? 1.0 : -1.0);
    }
  }
  int entryAxis = 0, exitAxis = 0;
  for (int k = 1; k < 3; ++k) {
    if (nearT[k] > nearT[entryAxis]) entryAxis = k;
    if (farT[k] < farT[exitAxis]) exitAxis = k;
  }
  const double t = nearT[entryAxis];
  if (std::isfinite(t) && std::isfinite(farT[exitAxis]))
    clearance.decide(farT[exitAxis] - t, entryAxis, exitAxis);
  if (!(t < farT[exitAxis])) {
    result.clearance = clearance.value;
    return result;  // the line misses the root cube (or only touches it)
  }

  // The entry point, on the entry face exactly; the other coordinates kept inside the cube.
  std::array<bool, 3> onFace{};
  glm::dvec3 p;
  for (int k = 0; k < 3; ++k) {
    onFace[k] = nearT[k] == t;
    p[k] = onFace[k] ? (d[k] > 0 ? -1.0 : 1.0) : std::clamp(o[k] + t * d[k], -1.0, 1.0);
  }
  int face = entryAxis;  // the axis of the plane the walk last crossed

  for (;;) {
    if (++result.cells > options.maxCells)
      throw std::runtime_error("voxel walk: more than " + std::to_string(options.maxCells) +
                               " cells on one ray");
    const Cell cell = locate(memory, root, p, d, options.maxLevel, result.farPointers);

    // How close the point where the ray entered this cell is to the cell's other faces: a ray
    // that close to an edge enters a neighbour instead under a small error of its t-values.
    for (int k = 0; k < 3; ++k) {
      if (onFace[k] || d[k] == 0.0) continue;
      clearance.decide((p[k] - cell.lower(k)) / d[k], face, k);
      clearance.decide((cell.upper(k) - p[k]) / d[k], face, k);
    }

    if (cell.leaf) {
      // The slab test of the voxel's box: the line enters it at its largest near-face t.
      double entry = -kInfinity;
      int axis = 0;
      for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) continue;
        const double near = crossing(o, d, k, d[k] > 0 ? cell.lower(k) : cell.upper(k));
        if (near > entry) entry = near, axis = k;
      }
      result.hit = true;
      result.tHit = entry;
      result.entryAxis = axis;
      result.level = cell.level;
      result.x = cell.index[0];
      result.y = cell.index[1];
      result.z = cell.index[2];
      result.voxelKey = cell.voxelKey;
      result.clearance = clearance.value;
      return result;
    }

    // An empty cell: leave it through its nearest far face.
    std::array<double, 3> exitT{};
    int axis = 0;
    for (int k = 0; k < 3; ++k) {
      exitT[k] = d[k] == 0.0 ? kInfinity
                             : crossing(o, d, k, d[k] > 0 ? cell.upper(k) : cell.lower(k));
      if (exitT[k] < exitT[axis]) axis = k;
    }
    const double tExit = exitT[axis];
    for (int k = 0; k < 3; ++k)
      if (k != axis && std::isfinite(exitT[k])) clearance.decide(exitT[k] - tExit, axis, k);
    // The next point: exactly on the exit face (and on every face the ray leaves by at the same
    // t, at a corner), the other coordinates kept inside this cell.
    for (int k = 0; k < 3; ++k) {
      onFace[k] = exitT[k] == tExit;
      p[k] = onFace[k] ? (d[k] > 0 ? cell.upper(k) : cell.lower(k))
                       : std::clamp(o[k] + tExit * d[k], cell.lower(k), cell.upper(k));
    }
    face = axis;
    // Leaving through a face of the root cube ends the walk: a miss.
    for (int k = 0; k < 3; ++k)
      if (onFace[k] && std::abs(p[k]) == 1.0) {
        result.clearance = clearance.value;
        return result;
      }
  }
}

}  // namespace rtu
