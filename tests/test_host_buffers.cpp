#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "base/binary_file.h"
#include "inputs/camera.h"
#include "inputs/host_buffers.h"

using namespace rtu;

namespace {

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rtusim_test_" + name)).string();
}

std::vector<uint32_t> jobWords() {
  Camera camera;
  camera.width = 4;
  camera.height = 3;
  return encodeJobRecords(makeFrameJobs(camera, 5));
}

}  // namespace

TEST_CASE("Job buffers round-trip through files in the driver's layout", "[buffers]") {
  Camera camera;
  camera.width = 8;
  camera.height = 5;
  const std::vector<TValueRecord> jobs = makeFrameJobs(camera, 3);
  const std::string path = tempPath("jobs.bin");
  writeJobBuffer(path, jobs);
  REQUIRE(std::filesystem::file_size(path) == jobs.size() * 32);
  const std::vector<uint32_t> words = readWordFile(path, 32, "jobs");
  REQUIRE(words[8 * 13] == (13u | static_cast<uint32_t>(jobs[13].a) << 28));  // id = x + y * w
  REQUIRE(words[8 * 13 + 7] == 3);
  const std::vector<TValueRecord> back = readJobBuffer(path);
  REQUIRE(back.size() == jobs.size());
  for (size_t i = 0; i < jobs.size(); ++i) {
    REQUIRE(back[i].idWord() == jobs[i].idWord());
    REQUIRE(back[i].t0Bits == jobs[i].t0Bits);
    REQUIRE(back[i].t1Bits == jobs[i].t1Bits);
  }
}

TEST_CASE("Malformed job buffers are rejected with the record and the reason", "[buffers]") {
  std::vector<uint32_t> words = jobWords();
  words[8 * 2] |= 0x80000000u;
  REQUIRE_THROWS_WITH(decodeJobRecords(words),
                      Catch::Contains("record 2") && Catch::Contains("bit 31"));
  words = jobWords();
  words[8 * 1 + 5] = 0x7FC00000u;  // NaN t1y
  REQUIRE_THROWS_WITH(decodeJobRecords(words),
                      Catch::Contains("record 1") && Catch::Contains("NaN"));
  words = jobWords();
  std::swap(words[8 * 4 + 3], words[8 * 4 + 6]);  // t0z <-> t1z
  REQUIRE_THROWS_WITH(decodeJobRecords(words), Catch::Contains("t0z > t1z"));

  const std::string path = tempPath("short.bin");
  std::ofstream(path, std::ios::binary) << std::string(33, '\0');
  REQUIRE_THROWS_WITH(readJobBuffer(path), Catch::Contains("33 bytes"));
  REQUIRE_THROWS_WITH(readJobBuffer(tempPath("does_not_exist")), Catch::Contains("cannot open"));
}

TEST_CASE("Impossible records are skipped and named, and the rest of the buffer is read",
          "[buffers]") {
  std::vector<uint32_t> words = jobWords();       // 12 jobs
  words[8 * 4 + 2] = 0x7FC00000u;                 // NaN t0y in record 4
  std::swap(words[8 * 9 + 1], words[8 * 9 + 4]);  // t0x <-> t1x in record 9
  const std::string path = tempPath("jobs_with_nan.bin");
  writeWordFile(path, words);
  std::vector<SkippedRecord> skipped;
  const std::vector<TValueRecord> jobs = readJobBufferSkipping(path, skipped);
  REQUIRE(skipped.size() == 2);
  CHECK(skipped[0].record == 4);
  CHECK_THAT(skipped[0].problem, Catch::Contains("record 4") && Catch::Contains("NaN"));
  CHECK(skipped[1].record == 9);
  REQUIRE(jobs.size() == 10);
  CHECK(jobs[4].id == 5);  // ids are x + y * width: record 5 follows record 3
  CHECK(jobs[8].id == 10);
  CHECK_THROWS_WITH(readJobBuffer(path), Catch::Contains("record 4"));
  words[8 * 2] |= 1u << 31;  // id bits: a file of another kind stops the reader all the same
  writeWordFile(path, words);
  CHECK_THROWS_WITH(readJobBufferSkipping(path, skipped), Catch::Contains("record 2: bit 31"));
  std::ofstream(path, std::ios::binary) << std::string(40, '\0');
  CHECK_THROWS_WITH(readJobBufferSkipping(path, skipped), Catch::Contains("40 bytes"));
  std::filesystem::remove(path);
}

// --total-bits 48 failed only when a t value happened not to fit while the results were written.
TEST_CASE("Formats over 32 bits get 12-word result records, invalid ones are refused before a run",
          "[buffers]") {
  CHECK(resultRecordWords(FixedFormat{32, 16}) == 8);
  CHECK(resultRecordWords(FixedFormat{8, 4}) == 8);
  CHECK(resultRecordWords(FixedFormat{33, 16}) == 12);
  CHECK(resultRecordWords(FixedFormat{48, 32}) == 12);
  CHECK_THROWS_WITH(resultRecordWords(FixedFormat{48, 47}),
                    Catch::Contains("format Q1.47 (48 bits)") && Catch::Contains("fraction bits"));
  CHECK_THROWS_WITH(resultRecordWords(FixedFormat{64, 16}),
                    Catch::Contains("format Q48.16 (64 bits)"));
}

TEST_CASE("Wide result records hold 48-bit t-values and normals, low word first", "[buffers]") {
  // Q16.32: t = -1.5 is -1.5 * 2^32 = -0x1'8000'0000, the normal 1.0 is 2^32.
  TraversalResult hit;
  hit.idWord = 5;
  hit.hit = true;
  hit.tHit = -(int64_t{3} << 31);
  hit.normal = {0, int64_t{1} << 32, 0};
  hit.cost = 9;
  hit.belowResolution = true;
  const std::vector<uint32_t> words = encodeResultRecords({hit}, kWideResultWords);
  REQUIRE(words == std::vector<uint32_t>{5, 1, 0x80000000u, 0xFFFFFFFEu, 0, 0, 0, 1, 0, 0, 9, 4});
  CHECK(decodeResultRecords(words, kWideResultWords)[0] == hit);
  const std::string path = tempPath("wide_results.bin");
  writeResultBuffer(path, {hit, hit}, kWideResultWords);
  CHECK(std::filesystem::file_size(path) == 2 * 48);
  CHECK(readResultBuffer(path, kWideResultWords)[1] == hit);
  CHECK_THROWS_WITH(decodeResultRecords(std::vector<uint32_t>(16), kWideResultWords),
                    Catch::Contains("not a multiple of 12"));
  std::filesystem::remove(path);
}

TEST_CASE("Result buffers round-trip and reject impossible records", "[buffers]") {
  TraversalResult hit;
  hit.idWord = 7 | 3u << 28;
  hit.hit = true;
  hit.tHit = -0x18000;
  hit.normal = {0, 0x10000, 0};
  hit.cost = 31;
  TraversalResult miss;
  miss.idWord = 8;
  miss.cost = 5;
  miss.stackOverflow = true;
  const std::vector<uint32_t> words = encodeResultRecords({hit, miss});
  REQUIRE(words == std::vector<uint32_t>{7 | 3u << 28, 1, 0xFFFE8000u, 0, 0x10000, 0, 31, 0, 8, 0,
                                         0, 0, 0, 0, 5, 1});
  const std::vector<TraversalResult> back = decodeResultRecords(words);
  REQUIRE(back[0] == hit);
  REQUIRE(back[1] == miss);

  std::vector<uint32_t> bad = words;
  bad[9] = 2;
  REQUIRE_THROWS_WITH(decodeResultRecords(bad),
                      Catch::Contains("record 1") && Catch::Contains("hit word"));
  bad = words;
  bad[12] = 0x10000;
  REQUIRE_THROWS_WITH(decodeResultRecords(bad), Catch::Contains("miss with a non-zero normal"));
  hit.tHit = int64_t{1} << 40;
  REQUIRE_THROWS_WITH(encodeResultRecords({hit}), Catch::Contains("32 bits"));
}

TEST_CASE("Buffers larger than a read chunk keep record numbers across chunks", "[buffers]") {
  Camera camera;
  camera.width = 250;
  camera.height = 160;  // 40,000 records, 1.28 MB: two chunks of 1 MiB
  const std::vector<TValueRecord> jobs = makeFrameJobs(camera, 7);
  const std::string path = tempPath("large_jobs.bin");
  writeJobBuffer(path, jobs);
  const std::vector<TValueRecord> back = readJobBuffer(path);
  REQUIRE(back.size() == jobs.size());
  CHECK(back.back().idWord() == jobs.back().idWord());
  CHECK(back.back().t1Bits == jobs.back().t1Bits);
  std::vector<uint32_t> words = encodeJobRecords(jobs);
  words[8 * 39000] |= 0x80000000u;  // in the second chunk (a chunk holds 32,768 records)
  writeWordFile(path, words);
  REQUIRE_THROWS_WITH(readJobBuffer(path),
                      Catch::Contains(path) && Catch::Contains("record 39000:"));
  std::filesystem::remove(path);
}

TEST_CASE("A result that does not fit leaves no result buffer behind", "[buffers]") {
  TraversalResult fits, tooWide;
  tooWide.hit = true;
  tooWide.tHit = int64_t{1} << 40;
  const std::string path = tempPath("unwritable_results.bin");
  REQUIRE_THROWS_WITH(writeResultBuffer(path, {fits, tooWide}), Catch::Contains("t_hit"));
  CHECK_FALSE(std::filesystem::exists(path));
}

TEST_CASE("Result flags: bit 0 stack overflow, bit 1 t overflow, bit 2 below resolution",
          "[buffers]") {
  TraversalResult wrapped;
  wrapped.tOverflow = true;
  TraversalResult both = wrapped;
  both.stackOverflow = true;
  TraversalResult fine;
  fine.belowResolution = true;
  const std::vector<uint32_t> words = encodeResultRecords({wrapped, both, fine});
  CHECK(words[7] == 2u);
  CHECK(words[15] == 3u);
  CHECK(words[23] == 4u);
  const std::vector<TraversalResult> back = decodeResultRecords(words);
  CHECK(back[0] == wrapped);
  CHECK(back[1] == both);
  CHECK(back[2] == fine);
  std::vector<uint32_t> unknown = words;
  unknown[7] = 8u;
  CHECK_THROWS_WITH(decodeResultRecords(unknown), Catch::Contains("unknown flag bits"));
}

TEST_CASE("A camera that makes no rays is refused naming its setting", "[camera]") {
  Camera camera;
  camera.up = {0.0, 0.0, 0.0};  // rendered an empty frame with exit 0
  CHECK_THROWS_WITH(camera.validate(), "camera.up must be a non-zero vector, got 0,0,0");
  camera.up = glm::dvec3(camera.lookAt - camera.position) * 3.0;
  CHECK_THROWS_WITH(camera.validate(), Catch::Contains("camera.up (") &&
                                           Catch::Contains(") is parallel to the view direction"));
  camera.up = {0.0, 1.0, 0.0};
  camera.position = {-1e308, 0.0, 0.0};
  camera.lookAt = {1e308, 0.0, 0.0};
  CHECK_THROWS_WITH(camera.validate(),
                    Catch::Contains("camera.position and camera.look_at are too far apart"));
  camera.lookAt = camera.position;
  CHECK_THROWS_WITH(camera.validate(),
                    Catch::Contains("camera.position and camera.look_at coincide"));
}
