#pragma once
// A triangle soup with shared vertices, as read from a mesh file, before voxelization.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "base/isolated_process.h"

namespace rtu {

struct TriangleMesh {
  std::vector<glm::dvec3> vertices;
  std::vector<std::array<uint32_t, 3>> triangles;  // indices into `vertices`
};

// The limits mesh loading runs under for an input of `fileBytes`: 10 s plus 3 s per MiB of
// wall-clock (and processor) time, and half the physical memory, at most 4 GiB. The
// environment variables RTUSIM_MESH_SECONDS and RTUSIM_MESH_MEMORY_MIB replace them; a value
// that is not a positive number is a std::runtime_error naming the variable.
ProcessLimits meshLoadLimits(uint64_t fileBytes);

// Reads OBJ, PLY (ASCII or binary) or another format assimp knows: polygons are triangulated,
// identical vertices joined, every mesh of the scene merged with its node transforms applied.
// Points and lines are dropped. A PLY header is checked first (ply_header_check.h); assimp then
// runs in a child process under `limits` (isolated_process.h), so a file that crashes assimp,
// hangs it or makes it allocate without bound is an error like any other. Throws
// std::runtime_error naming `path` when the file is missing, malformed, assimp cannot read it
// or exceeds the limits, it holds no triangle or a coordinate is not finite. assimp is called
// in librtusim_meshes.so (mesh_plugin.cpp), loaded on first use (plugin_loader.h): a missing
// module is a std::runtime_error naming it.
TriangleMesh loadTriangleMesh(const std::string& path, const ProcessLimits& limits);
// The same with meshLoadLimits(size of the file).
TriangleMesh loadTriangleMesh(const std::string& path);

}  // namespace rtu
