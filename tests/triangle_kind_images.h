#pragma once
// A triangle mesh built into each triangle kind's memory image as rtusim's builds build it (the
// BVH's binned SAH, seed 004's BIH on the c99 grid of the cube [-1, 1]^3, seed 001's PBRT k-d
// tree), with a model header of the identity placement after it: for hand-made scenes that every
// triangle kind traces alike (test_triangle_spans.cpp).

#include <cstdint>
#include <vector>

#include "kinds/bih/bih_builder.h"
#include "kinds/bih/bih_image.h"
#include "kinds/bih/bih_kind.h"
#include "kinds/bih/bih_model.h"
#include "kinds/bih/projected_triangle.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/bvh/bvh_model.h"
#include "kinds/bvh/sah_builder.h"
#include "kinds/kd/kd_image.h"
#include "kinds/kd/kd_kind.h"
#include "kinds/kd/pbrt_kd_builder.h"
#include "kinds/kd/trayracer_scene.h"
#include "rtu/model_header.h"
#include "rtu/word_memory.h"

namespace rtu {

struct KindImage {
  std::vector<uint32_t> words;  // the image at word 0, then its model header
  uint32_t header = 0;          // the model header's word address
  WordMemory memory() const { return WordMemory(words); }
};

template <class Kind>
KindImage kindImage(const TriangleMesh& mesh);

template <>
inline KindImage kindImage<BvhKind<>>(const TriangleMesh& mesh) {
  KindImage image{layOut(buildSah(mesh).tree, mesh).words, 0};
  image.header = appendBvhModelHeader(image.words, ModelPlacement{});
  return image;
}

// On the grid of the cube [-1, 1]^3 (the SVO's), which holds the mesh: a triangle in a face of
// the grid's box is out of the C99 kernel's sight (docs/precision.md), so a hand-made scene keeps
// its triangles inside.
template <>
inline KindImage kindImage<BihKind<>>(const TriangleMesh& mesh) {
  Aabb<double> cube;
  cube.lower = glm::dvec3(-1.0);
  cube.upper = glm::dvec3(1.0);
  const SceneGrid grid(cube, kC99Format);
  const ProjectedMesh projected = projectMesh(mesh, grid);
  const BihBuild tree = buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid));
  KindImage image{layOut(tree, projected, grid, BihIndexWidth::Wide).words, 0};
  image.header = appendBihModelHeader(image.words, grid, ModelPlacement{});
  return image;
}

template <>
inline KindImage kindImage<KdKind>(const TriangleMesh& mesh) {
  std::vector<glm::dvec3> corners, normals;
  for (const auto& triangle : mesh.triangles) {
    for (uint32_t v : triangle) corners.push_back(mesh.vertices[v]);
    normals.push_back(glm::dvec3(0.0, 0.0, 1.0));
  }
  const KdBuild tree = buildPbrtKd(pbrtTriangleBoxes(corners), PbrtKdParameters{});
  KindImage image{layOutKd(makeTrayRacerScene(tree, corners, normals, TrayRacerMaterial{})).words,
                  0};
  image.header = appendModelHeader(image.words, ModelPlacement{}, 0);
  return image;
}

}  // namespace rtu
