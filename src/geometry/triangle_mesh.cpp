#include "geometry/triangle_mesh.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "base/input_file.h"
#include "base/plugin_loader.h"
#include "geometry/obj_number_check.h"
#include "geometry/ply_header_check.h"

namespace rtu {
namespace {

// The mesh as the loading child sends it to the parent: vertex and triangle counts (u64 each),
// then the vertices (3 doubles each) and the triangles (3 u32 each), in this machine's layout.
constexpr size_t kCountsBytes = 2 * sizeof(uint64_t);
static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "vertices are sent as 3 doubles");
static_assert(sizeof(std::array<uint32_t, 3>) == 3 * sizeof(uint32_t), "triangles: 3 u32");

template <typename Element>
void appendElements(std::string& bytes, const std::vector<Element>& elements) {
  bytes.append(reinterpret_cast<const char*>(elements.data()), elements.size() * sizeof(Element));
}

std::string encodeMesh(const TriangleMesh& mesh) {
  const uint64_t counts[2] = {mesh.vertices.size(), mesh.triangles.size()};
  std::string bytes(reinterpret_cast<const char*>(counts), kCountsBytes);
  appendElements(bytes, mesh.vertices);
  appendElements(bytes, mesh.triangles);
  return bytes;
}

// The child is trusted no more than the file: the sizes must add up and every index must name a
// vertex before anything is allocated or used.
TriangleMesh decodeMesh(const std::string& bytes, const std::string& path) {
  const auto broken = [&] {
    return std::runtime_error("cannot read mesh '" + path +
                              "': the loading process sent a "
                              "malformed mesh");
  };
  if (bytes.size() < kCountsBytes) throw broken();
  uint64_t counts[2];
  std::memcpy(counts, bytes.data(), kCountsBytes);
  const uint64_t body = bytes.size() - kCountsBytes;
  if (counts[0] > body / sizeof(glm::dvec3) || counts[1] > body / sizeof(std::array<uint32_t, 3>) ||
      counts[0] * sizeof(glm::dvec3) + counts[1] * sizeof(std::array<uint32_t, 3>) != body)
    throw broken();
  TriangleMesh mesh;
  mesh.vertices.resize(counts[0]);
  mesh.triangles.resize(counts[1]);
  const char* next = bytes.data() + kCountsBytes;
  // An empty vector's data() may be null, which memcpy must not get even for 0 bytes.
  if (counts[0] > 0) std::memcpy(mesh.vertices.data(), next, counts[0] * sizeof(glm::dvec3));
  next += counts[0] * sizeof(glm::dvec3);
  if (counts[1] > 0)
    std::memcpy(mesh.triangles.data(), next, counts[1] * sizeof(std::array<uint32_t, 3>));
  for (const auto& triangle : mesh.triangles)
    for (uint32_t index : triangle)
      if (index >= counts[0]) throw broken();
  return mesh;
}

// Runs in the child process: assimp's part, in librtusim_meshes.so (src/geometry/mesh_plugin.cpp).
std::string loadWithAssimp(const std::string& path) {
  using LoadFunction = const char*(const char* path, void* mesh);
  LoadFunction* const load = pluginFunction<LoadFunction>(
      "librtusim_meshes.so", "rtusim_meshes_load", "needed to read meshes");
  TriangleMesh mesh;
  if (const char* error = load(path.c_str(), &mesh)) throw std::runtime_error(error);
  return encodeMesh(mesh);
}

void requireFinite(const TriangleMesh& mesh, const std::string& path) {
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3& v = mesh.vertices[i];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
      throw std::runtime_error("mesh '" + path + "': vertex " + std::to_string(i) +
                               " has a non-finite coordinate");
  }
}

// A positive number from the environment variable `name`, or `fallback` when it is unset.
double positiveFromEnvironment(const char* name, double fallback) {
  const char* text = std::getenv(name);
  if (text == nullptr) return fallback;
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value > 0) || value > 1e9)
    throw std::runtime_error(std::string("environment variable ") + name + "='" + text +
                             "': expected a positive number up to 1e9");
  return value;
}

uint64_t defaultMemoryBytes() {
  const auto physical = static_cast<uint64_t>(::sysconf(_SC_PHYS_PAGES)) *
                        static_cast<uint64_t>(::sysconf(_SC_PAGESIZE));
  return std::min(physical / 2, uint64_t{4} << 30);
}

}  // namespace

ProcessLimits meshLoadLimits(uint64_t fileBytes) {
  ProcessLimits limits;
  const double mebibytes = static_cast<double>(fileBytes) / (1 << 20);
  limits.seconds = positiveFromEnvironment("RTUSIM_MESH_SECONDS", 10 + 3 * mebibytes);
  limits.memoryBytes = static_cast<uint64_t>(
      positiveFromEnvironment("RTUSIM_MESH_MEMORY_MIB",
                              static_cast<double>(defaultMemoryBytes() >> 20)) *
      (1 << 20));
  return limits;
}

TriangleMesh loadTriangleMesh(const std::string& path, const ProcessLimits& limits) {
  inputFileBytes(path, "mesh file");
  checkPlyHeader(path);
  checkObjNumbers(path);
  std::string answer;
  try {
    answer = runIsolated([&] { return loadWithAssimp(path); }, limits);
  } catch (const IsolatedProcessError& error) {  // e.g. "assimp crashed (SIGSEGV)"
    throw std::runtime_error("cannot read mesh '" + path + "': assimp " + error.what());
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("cannot read mesh '" + path + "': " + error.what());
  }
  const TriangleMesh mesh = decodeMesh(answer, path);
  if (mesh.triangles.empty()) throw std::runtime_error("mesh '" + path + "' has no triangles");
  requireFinite(mesh, path);
  return mesh;
}

TriangleMesh loadTriangleMesh(const std::string& path) {
  return loadTriangleMesh(path, meshLoadLimits(inputFileBytes(path, "mesh file")));
}

}  // namespace rtu
