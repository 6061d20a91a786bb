#include "triangle_mesh.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/mat4x4.hpp>

namespace rtu {
namespace {

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

void requireFinite(const TriangleMesh& mesh, const std::string& path) {
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3& v = mesh.vertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw std::runtime_error("mesh '" + path + "': vertex " + std::to_string(i) +
                               " has a non-finite coordinate");
  }
}

}  // namespace

TriangleMesh loadTriangleMesh(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("mesh file '" + path + "' does not exist");
  Assimp::Importer importer;
  // Validation rejects out-of-range indices, so the walk below can trust the scene.
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                aiProcess_ValidateDataStructure);
  if (scene == nullptr)
    throw std::runtime_error("cannot read mesh '" + path + "': " + importer.GetErrorString());

  TriangleMesh mesh;
  if (scene->mRootNode != nullptr) appendNode(*scene, *scene->mRootNode, glm::dmat4(1.0), mesh);
  if (mesh.triangles.empty()) throw std::runtime_error("mesh '" + path + "' has no triangles");
  requireFinite(mesh, path);
  return mesh;
}

}  // namespace rtu
