#include "explore/accel_build.h"

#include <chrono>
#include <stdexcept>

#include "base/choice_list.h"
#include "explore/kind_scene.h"
#include "kind_explore_plugins.h"

namespace rtu {
namespace {

template <class Kind>
constexpr bool kBuildsStructure = KindScene<Kind>::kStructure != nullptr;

// Calls `visit(kind)` for each kind that builds a structure from triangles, in the registry's
// order.
template <class Visit>
void forEachStructure(Visit&& visit) {
  forEachCoreKind([&visit](auto kind) {
    if constexpr (kBuildsStructure<decltype(kind)>) visit(kind);
  });
}

}  // namespace

AccelBuild buildAccel(const TriangleMesh& mesh, const AccelSpec& spec, const RtuConfig& rtu) {
  std::optional<AccelBuild> build;
  const auto start = std::chrono::steady_clock::now();
  forEachStructure([&](auto kind) {
    using Scene = KindScene<decltype(kind)>;
    if (!build && spec.structure == Scene::kStructure) build = Scene::build(mesh, spec, rtu);
  });
  if (!build)
    throw std::invalid_argument("no triangle structure '" + spec.structure +
                                "': " + accelStructureNames());
  build->quality.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  build->quality.bytes = build->words.size() * sizeof(uint32_t);
  return std::move(*build);
}

std::string accelStructureNames() {
  std::vector<std::string> names;
  forEachStructure([&](auto kind) { names.push_back(KindScene<decltype(kind)>::kStructure); });
  return choiceList(names);
}

TriangleScene loadSceneTriangles(const RunConfig& settings) {
  const MeshDefectPolicy policy = settings.accel.dropBadTriangles ? MeshDefectPolicy::Drop
                                                                  : MeshDefectPolicy::Refuse;
  try {
    return loadTriangleScene(settings.scene, policy);
  } catch (const DroppableMeshDefects& error) {
    throw std::runtime_error(std::string(error.what()) + "; drop them with --drop-bad-triangles");
  }
}

}  // namespace rtu
