#include "embree_reference.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "geometry/aabb.h"

namespace rtu {
namespace {

// Embree's tree, built into nodes of our own through the builder's callbacks.
struct EmbreeNode {
  bool leaf = false;
  unsigned count = 0;            // a leaf's triangles
  EmbreeNode* children[2] = {};  // an inner node's
  Aabb<double> childBoxes[2];
};

void* createNode(RTCThreadLocalAllocator allocator, unsigned, void*) {
  return new (rtcThreadLocalAlloc(allocator, sizeof(EmbreeNode), 16)) EmbreeNode();
}
void setChildren(void* node, void** children, unsigned count, void*) {
  for (unsigned i = 0; i < count; ++i)
    static_cast<EmbreeNode*>(node)->children[i] = static_cast<EmbreeNode*>(children[i]);
}
void setBounds(void* node, const RTCBounds** bounds, unsigned count, void*) {
  for (unsigned i = 0; i < count; ++i)
    static_cast<EmbreeNode*>(node)->childBoxes[i] =
        Aabb<double>{{bounds[i]->lower_x, bounds[i]->lower_y, bounds[i]->lower_z},
                     {bounds[i]->upper_x, bounds[i]->upper_y, bounds[i]->upper_z}};
}
void* createLeaf(RTCThreadLocalAllocator allocator, const RTCBuildPrimitive*, size_t count, void*) {
  auto* leaf = new (rtcThreadLocalAlloc(allocator, sizeof(EmbreeNode), 16)) EmbreeNode();
  leaf->leaf = true;
  leaf->count = static_cast<unsigned>(count);
  return leaf;
}

// Σ_inner A + Σ_leaf A·n over the subtree of `node`, whose box is `box`.
double sahSum(const EmbreeNode& node, const Aabb<double>& box) {
  if (node.leaf) return box.area() * node.count;
  return box.area() + sahSum(*node.children[0], node.childBoxes[0]) +
         sahSum(*node.children[1], node.childBoxes[1]);
}

std::vector<RTCBuildPrimitive> primitivesOf(const TriangleMesh& mesh, Aabb<double>& root) {
  std::vector<RTCBuildPrimitive> primitives;
  primitives.reserve(mesh.triangles.size());
  for (unsigned t = 0; t < mesh.triangles.size(); ++t) {
    Aabb<double> box;
    for (uint32_t v : mesh.triangles[t]) box.grow(mesh.vertices[v]);
    const Aabb<float> stored = roundOutward(box);
    root.merge(box);
    primitives.push_back({stored.lower.x, stored.lower.y, stored.lower.z, 0, stored.upper.x,
                          stored.upper.y, stored.upper.z, t});
  }
  return primitives;
}

}  // namespace

EmbreeReference::EmbreeReference() : device_(rtcNewDevice("threads=1")) {
  if (!device_) throw std::runtime_error("Embree: no device");
}

EmbreeReference::~EmbreeReference() {
  if (scene_) rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

EmbreeReference::Build EmbreeReference::build(const TriangleMesh& mesh,
                                              RTCBuildQuality quality) const {
  Aabb<double> root;
  std::vector<RTCBuildPrimitive> primitives = primitivesOf(mesh, root);
  RTCBVH bvh = rtcNewBVH(device_);
  RTCBuildArguments arguments = rtcDefaultBuildArguments();
  arguments.buildQuality = quality;
  arguments.maxLeafSize = 8;
  arguments.bvh = bvh;
  arguments.primitives = primitives.data();
  arguments.primitiveCount = primitives.size();
  arguments.primitiveArrayCapacity = primitives.size();
  arguments.createNode = createNode;
  arguments.setNodeChildren = setChildren;
  arguments.setNodeBounds = setBounds;
  arguments.createLeaf = createLeaf;
  const auto start = std::chrono::steady_clock::now();
  const auto* tree = static_cast<const EmbreeNode*>(rtcBuildBVH(&arguments));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double sah = sahSum(*tree, root) / root.area();
  rtcReleaseBVH(bvh);
  return {sah, seconds};
}

void EmbreeReference::setScene(const TriangleMesh& mesh) {
  if (scene_) rtcReleaseScene(scene_);
  scene_ = rtcNewScene(device_);
  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               mesh.vertices.size()));
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    for (int k = 0; k < 3; ++k) vertices[3 * i + k] = static_cast<float>(mesh.vertices[i][k]);
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), mesh.triangles.size()));
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) indices[3 * t + k] = mesh.triangles[t][k];
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_);
}

std::optional<unsigned> EmbreeReference::intersect(const Ray& ray) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit hit{};
  hit.ray.org_x = static_cast<float>(ray.origin.x);
  hit.ray.org_y = static_cast<float>(ray.origin.y);
  hit.ray.org_z = static_cast<float>(ray.origin.z);
  hit.ray.dir_x = static_cast<float>(ray.direction.x);
  hit.ray.dir_y = static_cast<float>(ray.direction.y);
  hit.ray.dir_z = static_cast<float>(ray.direction.z);
  hit.ray.tnear = 0;
  hit.ray.tfar = INFINITY;
  hit.ray.mask = ~0u;
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &hit);
  if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return hit.hit.primID;
}

}  // namespace rtu
