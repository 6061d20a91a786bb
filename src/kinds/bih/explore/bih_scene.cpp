#include "kinds/bih/explore/bih_scene.h"

#include <utility>

#include "geometry/ray_sets.h"
#include "kinds/bih/bih_builder.h"
#include "kinds/bih/bih_config.h"
#include "kinds/bih/bih_image.h"
#include "kinds/bih/bih_model.h"
#include "kinds/bih/bih_quality.h"

namespace rtu {

AccelBuild KindScene<BihKind<>>::build(const TriangleMesh& mesh, const AccelSpec& spec,
                                       const RtuConfig& rtu) {
  const FixedTriangleFormat& format = rtu.coreConfig<BihKind<>>().format;
  const SceneGrid grid(gridBoxAround(meshBounds(mesh), format), format);
  const ProjectedMesh projected = projectMesh(mesh, grid);
  const BihBuild tree = buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid));
  const BihIndexWidth width = spec.index == "wide" ? BihIndexWidth::Wide : BihIndexWidth::Seed;
  BihImage image = layOut(tree, projected, grid, width);
  AccelBuild build;
  build.words = std::move(image.words);
  build.warnings = std::move(image.warnings);
  if (projected.degenerate > 0)
    build.warnings.push_back(std::to_string(projected.degenerate) +
                             " triangles have no area once on the grid and are left out");
  build.quality = measureQuality(tree, sceneUpper(grid));
  build.description = "BIH (" + bihFormatName(format) + " formats, " + spec.index + " indices)";
  return build;
}

uint32_t KindScene<BihKind<>>::appendModelHeader(std::vector<uint32_t>& words,
                                                 const TriangleMesh& mesh,
                                                 const ModelPlacement& placement,
                                                 const RunConfig& settings) {
  const FixedTriangleFormat& format = settings.rtu.coreConfig<BihKind<>>().format;
  const SceneGrid grid(gridBoxAround(meshBounds(mesh), format), format);
  return appendBihModelHeader(words, grid, placement);
}

std::string KindScene<BihKind<>>::buildKey(const RunConfig& settings) {
  return bihFormatName(settings.rtu.coreConfig<BihKind<>>().format);
}

}  // namespace rtu
