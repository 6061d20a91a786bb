#pragma once
// An animated scene file's frame as one triangle mesh in the world (issue 30, `rtusim compare
// --scene-file`): every instance's model as triangles (a mesh file fitted into the model's cube as
// the voxelizer fits it at the model's depth, a voxel scene's faces where they lie in the cube),
// placed by the instance's keyframes at `time`; and the camera of the camera path then. So every
// architecture traces the same surface: the triangle kinds the mesh, the SVO its voxels.

#include <string>

#include "geometry/triangle_mesh.h"
#include "inputs/camera.h"
#include "scene/scene_file.h"

namespace rtu {

struct SceneMesh {
  TriangleMesh mesh;  // in the world
  Camera camera;      // at `time`, the file's frame size
};

// A model's triangles in its cube (the mesh fitted as the voxelizer fits it, a voxel scene's
// faces); throws what loading them throws, naming the model. The two-level BVH's meshes
// (kinds/bvh/explore/two_level_animation.h).
TriangleMesh sceneModelMesh(const ModelDescription& model);

// Throws what loading a model's triangles throws (an .svo model holds none), naming the model;
// degenerate and duplicate triangles of a model's mesh are dropped.
SceneMesh sceneMesh(const SceneDescription& scene, double time);

// The mesh as an OBJ file (vertices in %.17g, so a reader in double reads them back exactly).
void writeObjMesh(const std::string& path, const TriangleMesh& mesh);

}  // namespace rtu
