// Triangle BVH builds and golden traversal against Embree 3: per mesh, each builder's build time
// (best of 5) and SAH (unit costs), Embree's builder at low, medium and high quality (leaves of
// 1-8, object splits only), and the golden BVH traversal's rays per second on 4 views of 128x128
// primary rays against rtcIntersect1 on the same float32 triangles, one thread each. Not a test:
// run it and record the figures in docs/performance.md.
//   build/bench/triangle_bench [mesh ...]    (default: the assimp spider and Wuson; the CGAL
//                                             meshes come from bench/cgal_meshes.sh)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "embree_reference.h"
#include "geometry/mesh_checks.h"
#include "geometry/ray_sets.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/bvh/bvh_quality.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/lbvh_builder.h"
#include "kinds/bvh/sah_builder.h"
#include "rtu/golden_shell.h"

using namespace rtu;

namespace {

constexpr int kRepetitions = 5;

template <class Work>
double bestSeconds(Work&& work) {
  double best = 1e30;
  for (int i = 0; i < kRepetitions; ++i) {
    const auto start = std::chrono::steady_clock::now();
    work();
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

struct Builder {
  const char* name;
  std::function<BuildTree(const TriangleMesh&)> build;
};

const std::vector<Builder>& builders() {
  static const std::vector<Builder> all = {
      {"langr", [](const TriangleMesh& m) { return buildLangr(m).tree; }},
      {"binned", [](const TriangleMesh& m) { return buildSah(m).tree; }},
      {"sweep",
       [](const TriangleMesh& m) {
         SahBuilderConfig config;
         config.search = SahSplitSearch::Sweep;
         return buildSah(m, config).tree;
       }},
      {"lbvh", [](const TriangleMesh& m) { return buildLbvh(m).tree; }}};
  return all;
}

void benchBuilds(const TriangleMesh& mesh, const EmbreeReference& embree) {
  const SahCosts unit{1.0, 1.0};
  for (const Builder& builder : builders()) {
    BuildTree tree;
    const double seconds = bestSeconds([&] { tree = builder.build(mesh); });
    std::printf("  %-14s %10.2f ms %8.1f ns/tri  SAH %7.2f\n", builder.name, 1e3 * seconds,
                1e9 * seconds / mesh.triangles.size(), measureQuality(tree, unit).sah);
  }
  const std::pair<const char*, RTCBuildQuality> qualities[] = {
      {"embree low", RTC_BUILD_QUALITY_LOW},
      {"embree medium", RTC_BUILD_QUALITY_MEDIUM},
      {"embree high", RTC_BUILD_QUALITY_HIGH}};
  for (const auto& [name, quality] : qualities) {
    EmbreeReference::Build best{0, 1e30};
    for (int i = 0; i < kRepetitions; ++i) {
      const EmbreeReference::Build build = embree.build(mesh, quality);
      if (build.seconds < best.seconds) best = build;
    }
    std::printf("  %-14s %10.2f ms %8.1f ns/tri  SAH %7.2f\n", name, 1e3 * best.seconds,
                1e9 * best.seconds / mesh.triangles.size(), best.sah);
  }
}

void benchTraversal(const TriangleMesh& mesh, EmbreeReference& embree) {
  const std::vector<Ray> rays = viewRays(meshBounds(mesh), 4, 128, 128);
  const BvhImage image = layOut(buildSah(mesh).tree, mesh);
  const BvhSections sections = sectionsOf(BvhImageView(image.words).header());
  GoldenShell<BvhKind<WatertightIntersector>> shell(image.memory(), BvhConfig{});
  std::vector<BvhJob> jobs;
  for (const Ray& ray : rays)
    jobs.push_back(
        {makeBvhRay(glm::vec3(ray.origin), glm::vec3(ray.direction), 0, INFINITY), sections});
  size_t goldenHits = 0, embreeHits = 0, sameTriangle = 0;
  std::vector<BvhResult> results(jobs.size());
  const double golden = bestSeconds([&] {
    for (size_t i = 0; i < jobs.size(); ++i) shell.run(0, jobs[i], results[i]);
  });
  embree.setScene(mesh);
  std::vector<std::optional<unsigned>> hits(rays.size());
  const double reference = bestSeconds([&] {
    for (size_t i = 0; i < rays.size(); ++i) hits[i] = embree.intersect(rays[i]);
  });
  for (size_t i = 0; i < rays.size(); ++i) {
    goldenHits += results[i].hit;
    embreeHits += hits[i].has_value();
    sameTriangle += results[i].hit && hits[i] && *hits[i] == results[i].primitive;
  }
  std::printf("  traversal: golden BVH (binned, watertight) %.2f M rays/s, Embree rtcIntersect1 "
              "%.2f M rays/s: %.2f of Embree's speed\n",
              rays.size() / golden / 1e6, rays.size() / reference / 1e6, reference / golden);
  std::printf("             %zu rays: %zu golden hits, %zu Embree hits, %zu on the same triangle\n",
              rays.size(), goldenHits, embreeHits, sameTriangle);
}

// The registered kind's triangle test chosen at run time (SelectedIntersector: one branch per
// test) against the test fixed at compile time, on the same jobs: the two traced in turn, 15
// times each, and the best of each taken, so that a load on the machine meets both alike.
template <class Intersector>
double traceOnce(const BvhImage& image, const std::vector<BvhJob>& jobs, const BvhConfig& config) {
  GoldenShell<BvhKind<Intersector>> shell(image.memory(), config);
  std::vector<BvhResult> results(jobs.size());
  const auto start = std::chrono::steady_clock::now();
  for (size_t i = 0; i < jobs.size(); ++i) shell.run(0, jobs[i], results[i]);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

template <class Fixed>
std::pair<double, double> bestOfInTurn(const BvhImage& image, const std::vector<BvhJob>& jobs,
                                       const BvhConfig& config) {
  double selected = 1e30, fixed = 1e30;
  for (int i = 0; i < 15; ++i) {
    selected = std::min(selected, traceOnce<SelectedIntersector>(image, jobs, config));
    fixed = std::min(fixed, traceOnce<Fixed>(image, jobs, config));
  }
  return {selected, fixed};
}

void benchSelectedTest(const TriangleMesh& mesh) {
  const std::vector<Ray> rays = viewRays(meshBounds(mesh), 4, 128, 128);
  const BvhImage image = layOut(buildSah(mesh).tree, mesh);
  const BvhSections sections = sectionsOf(BvhImageView(image.words).header());
  std::vector<BvhJob> jobs;
  for (const Ray& ray : rays)
    jobs.push_back(
        {makeBvhRay(glm::vec3(ray.origin), glm::vec3(ray.direction), 0, INFINITY), sections});
  BvhConfig watertight, moller;
  moller.triangleTest = TriangleTest::MollerTrumbore;
  const auto [selectedW, fixedW] = bestOfInTurn<WatertightIntersector>(image, jobs, watertight);
  const auto [selectedM, fixedM] = bestOfInTurn<MollerTrumboreIntersector>(image, jobs, moller);
  std::printf("  test chosen at run time / at compile time: watertight %.2f / %.2f M rays/s "
              "(time %.3f), moller-trumbore %.2f / %.2f M rays/s (time %.3f)\n",
              rays.size() / selectedW / 1e6, rays.size() / fixedW / 1e6, selectedW / fixedW,
              rays.size() / selectedM / 1e6, rays.size() / fixedM / 1e6, selectedM / fixedM);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths(argv + 1, argv + argc);
  if (paths.empty())
    paths = {"/usr/share/assimp/models/OBJ/spider.obj",
             "/usr/share/assimp/models/OBJ/WusonOBJ.obj"};
  EmbreeReference embree;
  std::printf("triangle BVH builds (best of %d, 1 thread) and traversal against Embree %d.%d.%d\n",
              kRepetitions, RTC_VERSION_MAJOR, RTC_VERSION_MINOR, RTC_VERSION_PATCH);
  for (const std::string& path : paths) {
    TriangleMesh mesh = loadTriangleMesh(path);
    const size_t dropped = checkTriangleMesh(mesh, path, MeshDefectPolicy::Drop).size();
    std::printf("%s: %zu triangles (%zu degenerate or duplicate dropped)\n", path.c_str(),
                mesh.triangles.size(), dropped);
    benchBuilds(mesh, embree);
    benchTraversal(mesh, embree);
    benchSelectedTest(mesh);
  }
  return 0;
}
