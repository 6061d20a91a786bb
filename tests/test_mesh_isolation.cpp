// Mesh loading survives files that crash, hang or exhaust assimp (issue 12): the child process
// of isolated_process.h, the PLY header check and the reproducers of the issue.
#include <unistd.h>

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "base/isolated_process.h"
#include "geometry/triangle_mesh.h"

using Catch::Matchers::Contains;
using rtu::IsolatedProcessError;
using rtu::ProcessLimits;
using rtu::runIsolated;

namespace {

const std::string kMalformed = std::string(RTUSIM_TEST_DATA) + "/malformed/";

double secondsOf(const std::function<void()>& action) {
  const auto start = std::chrono::steady_clock::now();
  try {
    action();
  } catch (...) {
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

ProcessLimits smallLimits() {
  ProcessLimits limits;
  limits.seconds = 1;
  limits.memoryBytes = uint64_t{64} << 20;
  return limits;
}

}  // namespace

TEST_CASE("runIsolated hands back the child's answer, larger than a pipe's buffer", "[mesh]") {
  std::string expected(3 << 20, '\0');
  for (size_t i = 0; i < expected.size(); ++i) expected[i] = static_cast<char>(i * 7 % 251);
  CHECK(runIsolated([&] { return expected; }, ProcessLimits{}) == expected);
}

TEST_CASE("runIsolated turns the child's failures into errors", "[mesh]") {
  SECTION("an exception keeps its message") {
    CHECK_THROWS_WITH(runIsolated([]() -> std::string { throw std::runtime_error("bad vertex"); },
                                  smallLimits()),
                      "bad vertex");
  }
  SECTION("a crash names the signal") {
    CHECK_THROWS_MATCHES(runIsolated([]() -> std::string { std::abort(); }, smallLimits()),
                         IsolatedProcessError, Catch::Message("crashed (SIGABRT)"));
    CHECK_THROWS_MATCHES(runIsolated(
                             []() -> std::string {
                               std::raise(SIGSEGV);
                               return {};
                             },
                             smallLimits()),
                         IsolatedProcessError, Catch::Message("crashed (SIGSEGV)"));
  }
  SECTION("a hang is killed at the time limit") {
    const auto spin = []() -> std::string {
      for (volatile unsigned i = 0;; i = i + 1) {
      }
    };
    CHECK_THROWS_WITH(runIsolated(spin, smallLimits()), Contains("did not finish within 1 s"));
    CHECK(secondsOf([&] { runIsolated(spin, smallLimits()); }) < 5);
  }
  SECTION("a hang without using the processor is killed too") {
    const auto sleep = []() -> std::string {
      for (;;) pause();
    };
    CHECK_THROWS_WITH(runIsolated(sleep, smallLimits()), "did not finish within 1 s");
  }
  SECTION("an allocation beyond the memory limit") {
    // One large block, as a count read from a file asks for. (Many small ones would exhaust the
    // memory AddressSanitizer needs for its own report, in the sanitizer build.)
    const auto hog = []() -> std::string {
      const std::vector<char> block(size_t{1} << 30, 'x');
      return std::string(1, block.back());
    };
    CHECK_THROWS_MATCHES(runIsolated(hog, smallLimits()), IsolatedProcessError,
                         Catch::Message("needed more than 64 MiB of memory"));
  }
}

TEST_CASE("Meshes that crashed, hung or exhausted rtusim now give an error naming them", "[mesh]") {
  const auto expectError = [](const std::string& name, const std::string& problem) {
    const std::string path = kMalformed + "ply/" + name;
    CHECK_THROWS_WITH(rtu::loadTriangleMesh(path), Contains("'" + path + "'") && Contains(problem));
    CHECK(secondsOf([&] { rtu::loadTriangleMesh(path); }) < 5);
  };
  expectError("no-end-header.ply", "PLY header has no end_header line");
  expectError("binary-end-header-without-newline.ply", "PLY header has no end_header line");
  expectError("binary-0xff-before-end-header.ply", "PLY header line 8 is not text");
  expectError("face-of-0-vertices-alone.ply", "assimp crashed (SIGABRT)");
  // Refused by the ASCII body check before assimp (which crashed, or asked for 32 GiB).
  expectError("face-of-0-vertices.ply", "'face' element 1 of the 1 declared (body line 4)");
  expectError("face-of-minus-1-vertices.ply", "'face' element 1 of the 1 declared (body line 4)");
  expectError("face-of-4294967295-vertices.ply", "'face' element 1 of the 1 declared");
  expectError("element-count-not-a-number.ply", "element 'vertex' has the count '3x'");
  expectError("element-count-beyond-the-file.ply",
              "declares 1000000 'face' elements but only 50 bytes follow the header");
}

TEST_CASE("An ASCII PLY holds the elements its header declares\\, each on its line", "[mesh]") {
  const auto problem = [](const std::string& name) {
    const std::string path = kMalformed + "ply/" + name;
    try {
      rtu::loadTriangleMesh(path);
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("loaded");
  };
  // assimp read these as other models: a face as the fifth vertex, or a vertex as a face.
  CHECK(problem("more-vertices-declared-than-held.ply") ==
        "mesh '" + kMalformed +
            "ply/more-vertices-declared-than-held.ply': PLY header does not match the data: "
            "'vertex' element 5 of the 5 declared (body line 5) has 4 values");
  CHECK_THAT(problem("more-faces-declared-than-held.ply"),
             Contains("declares more data than the file holds: 'face' element 3 of the 3 "
                      "declared is missing"));
  CHECK_THAT(problem("fewer-vertices-declared-than-held.ply"),
             Contains("'face' element 1 of the 1 declared (body line 4) has 3 values"));
}

TEST_CASE("A binary PLY holds the elements its header declares\\, counted against its size",
          "[mesh]") {
  const auto problem = [](const std::string& name) {
    const std::string path = kMalformed + "ply/" + name;
    try {
      rtu::loadTriangleMesh(path);
    } catch (const std::runtime_error& error) {
      return std::string(error.what());
    }
    return std::string("loaded");
  };
  // The tetrahedron of 4 vertices (12 bytes each) and 4 faces (a count byte, 3 indices: 13 bytes).
  CHECK_THAT(problem("binary-body-cut-short.ply"),
             Contains("declares more data than the file holds: 'face' element 4 of the 4 "
                      "declared is cut off"));
  CHECK_THAT(problem("binary-body-longer-than-declared.ply"),
             Contains("declares less data than the file holds: 13 bytes follow the last element"));
  CHECK_THAT(problem("binary-more-vertices-than-the-file-holds.ply"),
             Contains("declares more data than the file holds: 20 'vertex' elements of 12 bytes, "
                      "100 bytes left for them"));
}

TEST_CASE("Mesh loading limits come from the input size or the environment", "[mesh]") {
  ::unsetenv("RTUSIM_MESH_SECONDS");
  ::unsetenv("RTUSIM_MESH_MEMORY_MIB");
  CHECK(rtu::meshLoadLimits(0).seconds == 10);
  CHECK(rtu::meshLoadLimits(uint64_t{4} << 20).seconds == 22);
  CHECK(rtu::meshLoadLimits(0).memoryBytes <= uint64_t{4} << 30);
  ::setenv("RTUSIM_MESH_SECONDS", "2.5", 1);
  ::setenv("RTUSIM_MESH_MEMORY_MIB", "100", 1);
  CHECK(rtu::meshLoadLimits(uint64_t{4} << 20).seconds == 2.5);
  CHECK(rtu::meshLoadLimits(0).memoryBytes == uint64_t{100} << 20);
  ::setenv("RTUSIM_MESH_SECONDS", "-1", 1);
  CHECK_THROWS_WITH(rtu::meshLoadLimits(0), Contains("RTUSIM_MESH_SECONDS='-1'"));
  ::setenv("RTUSIM_MESH_SECONDS", "5s", 1);
  CHECK_THROWS_WITH(rtu::meshLoadLimits(0), Contains("RTUSIM_MESH_SECONDS='5s'"));
  ::unsetenv("RTUSIM_MESH_SECONDS");
  ::unsetenv("RTUSIM_MESH_MEMORY_MIB");
}

TEST_CASE("The PLY header check lets UTF-8 comments through", "[mesh]") {
  const rtu::TriangleMesh mesh =
      rtu::loadTriangleMesh(std::string(RTUSIM_TEST_DATA) + "/meshes/tetrahedron-utf8-comment.ply");
  CHECK(mesh.triangles.size() == 4);
  CHECK(mesh.vertices.size() == 4);
}

TEST_CASE("OBJ values that are not decimal numbers are refused\\, not read as 0", "[mesh]") {
  // assimp read the hexadecimal float 0x1p3 (8) as 0: a flat triangle of another model.
  const std::string path = kMalformed + "obj/hexadecimal-float.obj";
  CHECK_THROWS_WITH(rtu::loadTriangleMesh(path),
                    "mesh '" + path + "', line 2: '0x1p3' is not a decimal number");
}
