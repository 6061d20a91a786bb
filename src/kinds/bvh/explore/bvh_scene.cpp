#include "kinds/bvh/explore/bvh_scene.h"

#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_quality.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/lbvh_builder.h"
#include "kinds/bvh/sah_builder.h"

namespace rtu {
namespace {

BuildTree buildBvhTree(const TriangleMesh& mesh, const std::string& builder) {
  if (builder == "langr") return buildLangr(mesh).tree;
  if (builder == "lbvh") return buildLbvh(mesh).tree;
  SahBuilderConfig config;
  config.search = builder == "sweep" ? SahSplitSearch::Sweep : SahSplitSearch::Binned;
  return buildSah(mesh, config).tree;
}

}  // namespace

AccelBuild KindScene<BvhKind<>>::build(const TriangleMesh& mesh, const AccelSpec& spec,
                                       const RtuConfig&) {
  const BuildTree tree = buildBvhTree(mesh, spec.builder);
  AccelBuild build;
  build.words = layOut(tree, mesh).words;
  build.quality = measureQuality(tree, SahCosts{1.0, 2.0});  // seed 003's box 1, triangle 2
  build.description = spec.builder + " BVH";
  build.settings = {{"builder", spec.builder}};
  return build;
}

}  // namespace rtu
