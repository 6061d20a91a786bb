// librtusim_meshes.so: the assimp half of loadTriangleMesh (src/geometry/triangle_mesh.cpp), loaded
// with dlopen on first use so that only commands reading a mesh load assimp.

#include <string>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/mat4x4.hpp>

#include "base/plugin_entry.h"
#include "geometry/triangle_mesh.h"

namespace {

using rtu::TriangleMesh;

glm::dmat4 toGlm(const aiMatrix4x4& m) {
  glm::dmat4 result;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 4; ++column) result[column][row] = m[row][column];
  return result;
}

void appendMesh(const aiMesh& mesh, const glm::dmat4& transform, TriangleMesh& out) {
  const auto first = static_cast<uint32_t>(out.vertices.size());
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const aiVector3D& v = mesh.mVertices[i];
    out.vertices.emplace_back(transform * glm::dvec4(v.x, v.y, v.z, 1.0));
  }
  for (unsigned i = 0; i < mesh.mNumFaces; ++i) {
    const aiFace& face = mesh.mFaces[i];
    if (face.mNumIndices != 3) continue;  // a point or a line: no surface to voxelize
    out.triangles.push_back(
        {first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]});
  }
}

// A mesh used by several nodes is instanced once per node.
void appendNode(const aiScene& scene, const aiNode& node, const glm::dmat4& parentTransform,
                TriangleMesh& out) {
  const glm::dmat4 transform = parentTransform * toGlm(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i)
    appendMesh(*scene.mMeshes[node.mMeshes[i]], transform, out);
  for (unsigned i = 0; i < node.mNumChildren; ++i)
    appendNode(scene, *node.mChildren[i], transform, out);
}

}  // namespace

RTUSIM_PLUGIN_ABI_ENTRY

// Appends every triangle of the mesh file at `path` to `*mesh` (an rtu::TriangleMesh: caller and
// module are built from the same header by the same compiler, as kPluginAbi checks). Returns
// nullptr, or the error message (valid until the thread's next call) when assimp cannot read
// the file.
RTUSIM_PLUGIN_EXPORT const char* rtusim_meshes_load(const char* path, void* mesh) {
  return rtu::pluginCall([&]() -> std::string {
    Assimp::Importer importer;
    // Validation rejects out-of-range indices, so the walk below can trust the scene.
    const aiScene* scene =
        importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                    aiProcess_ValidateDataStructure);
    if (scene == nullptr) return std::string("assimp: ") + importer.GetErrorString();
    if (scene->mRootNode != nullptr)
      appendNode(*scene, *scene->mRootNode, glm::dmat4(1.0), *static_cast<TriangleMesh*>(mesh));
    return {};
  });
}
