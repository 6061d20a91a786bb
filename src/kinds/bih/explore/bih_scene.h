#pragma once
// The BIH kind's frame scene (explore/kind_scene.h): seed 004's BIH on the n-bit grid of its number
// formats (the kind's `format`), whose model space is that grid (bih_model.h).

#include <string>
#include <vector>

#include "explore/kind_scene.h"
#include "kinds/bih/bih_kind.h"

namespace rtu {

template <>
struct KindScene<BihKind<>> : TriangleKindScene<BihKind<>> {
  static constexpr const char* kStructure = "bih";
  static AccelBuild build(const TriangleMesh& mesh, const AccelSpec& spec, const RtuConfig& rtu);
  // The grid's model header (appendBihModelHeader): the grid `format` puts the mesh on.
  static uint32_t appendModelHeader(std::vector<uint32_t>& words, const TriangleMesh& mesh,
                                    const ModelPlacement& placement, const RunConfig& settings);
  // The number formats, which change the grid and the image.
  static std::string buildKey(const RunConfig& settings);
};

}  // namespace rtu
