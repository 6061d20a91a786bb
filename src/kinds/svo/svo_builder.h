#pragma once
// Builds the SVO memory image of a voxel source (thesis section 4.2).
//
// Layout: the root descriptor at the requested address; below every descriptor with non-leaf
// children, a block holding those children's descriptors in slot order, then the far words this
// block needs, then the blocks below each child in turn (depth first). A child pointer is
// relative to its descriptor; when it does not fit in 15 bits the descriptor's far flag is set
// and its pointer names a far word, stored right after its block, that holds the 32-bit offset.
// Uniform subtrees collapse: an all-solid node becomes a leaf of its parent.

#include <cstddef>
#include <cstdint>
#include <string>

#include "kinds/svo/svo_image.h"
#include "kinds/svo/voxel_source.h"

namespace rtu {

struct SvoStats {
  size_t descriptors = 0;
  size_t farPointers = 0;
  size_t leaves = 0;  // solid children (collapsed regions count once)
  int depth = 0;      // deepest level holding a leaf; the root cube is level 0
  size_t words = 0;
  size_t bytes() const { return words * 4; }

  std::string describe() const;  // one line for reports
};

struct SvoBuild {
  SvoImage image;
  SvoStats stats;
};

// Words before `rootAddress` are zero. Throws std::invalid_argument if the source's depth is not
// in [1, kMaxSvoDepth] or it answers Mixed for a voxel.
SvoBuild buildSvo(const VoxelSource& source, uint32_t rootAddress = 0);

constexpr int kMaxSvoDepth = 16;
// Highest root address of a built image: the words before it are written as zeros.
constexpr uint32_t kMaxBuildRoot = uint32_t{1} << 26;

}  // namespace rtu
