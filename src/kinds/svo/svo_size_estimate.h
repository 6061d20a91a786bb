#pragma once
// What building a voxel source's tree will take, known before building it: the upper levels are
// counted exactly (the nodes the source answers Mixed become descriptors), the levels below are
// extrapolated at the growth of the last level counted. Cheap: at most a few hundred thousand
// classify calls however deep the tree.

#include <cstdint>

#include "kinds/svo/voxel_source.h"

namespace rtu {

struct SvoSizeEstimate {
  double descriptors = 0;  // an upper bound for exact counts: uniform children still collapse
  double imageBytes = 0;   // descriptors plus the zero words before the root
  double peakBytes = 0;    // the builder's peak: subtrees are copied into their parent's block
};

SvoSizeEstimate estimateSvoSize(const VoxelSource& source, uint32_t rootAddress);

}  // namespace rtu
