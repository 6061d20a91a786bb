#pragma once
// One place that turns "which scene" into an SVO image: a procedural scene, a triangle mesh
// (OBJ/PLY), a .binvox voxel file or a ready .svo image (validated before use); or into the
// triangles a triangle structure is built over.

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/mesh_checks.h"
#include "geometry/triangle_mesh.h"
#include "kinds/svo/svo_image.h"

namespace rtu {

struct SceneSpec {
  std::string procedural = "menger";  // used when no file is given
  std::string svoFile;
  std::string meshFile;
  std::string binvoxFile;
  int depth = 8;  // octree depth for procedural scenes and meshes
  uint64_t seed = 1;
  uint32_t root = 0;  // root descriptor address of an .svo file, or where to build the root
  int maxDepth = 16;  // deepest octree an .svo file may have
};

struct Scene {
  SvoImage image;
  std::string name;     // e.g. "menger (depth 8)" or the file name
  std::string summary;  // descriptors, leaves, far pointers, depth, bytes
  int depth = 0;
};

// Throws std::invalid_argument when more than one source is given, std::runtime_error for
// unreadable or malformed files.
Scene loadScene(const SceneSpec& spec);
// What messages call the scene: "SVO image 'f.svo'", "mesh 'f.obj'", "scene 'sphere'".
std::string sceneSource(const SceneSpec& scene);

struct TriangleScene {
  TriangleMesh mesh;
  std::string name;  // e.g. "menger (depth 5, voxel faces)" or the file name
  // The file's ids of the degenerate and duplicate triangles dropped (MeshDefectPolicy::Drop),
  // ascending: mesh triangle k is the file's k-th id not among them (checkTriangleMesh).
  std::vector<uint32_t> dropped;
};

// The scene's triangles: a mesh file's, checked (geometry/mesh_checks.h) under `policy`, or a
// voxel scene's exposed faces (a procedural scene or a .binvox file, kinds/svo/voxel_faces.h).
// Throws as loadScene does, and std::invalid_argument for an .svo image, which holds no triangles.
TriangleScene loadTriangleScene(const SceneSpec& spec, MeshDefectPolicy policy);

}  // namespace rtu
