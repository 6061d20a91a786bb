// Ray records and the job manager's model transform (thesis 6.2.1, stages one and two): records
// and headers in memory, the set-up against the driver's, and moved models seen from moved rays.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <glm/geometric.hpp>

#include "inputs/camera.h"
#include "inputs/host_buffers.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"

using namespace rtu;

namespace {

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rtusim_test_" + name)).string();
}

Camera smallCamera(int width, int height) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  return camera;
}

std::vector<uint32_t> rayWords() {
  return encodeRayRecords(makeFrameRayRecords(smallCamera(4, 3), 9));
}

// The image of `scene` with a model header placed at `placement` after it; returns its address.
struct PlacedModel {
  SvoImage image;
  uint32_t header = 0;
};

PlacedModel placedModel(const std::string& scene, const ModelPlacement& placement) {
  PlacedModel model{buildSvo(*makeProceduralScene(scene, 6)).image, 0};
  model.header = appendModelHeader(model.image, placement);
  return model;
}

// Distance of two floats in units in the last place of `scale`: the ulp of the largest magnitude
// the set-up's final add works with.
double ulpsAt(float a, float b, float scale) {
  const float magnitude = std::abs(scale);
  const float ulp = std::nextafter(magnitude, std::numeric_limits<float>::infinity()) - magnitude;
  return std::abs(static_cast<double>(a) - static_cast<double>(b)) / ulp;
}

bool driverRenormalises(const RayRecord& record) {
  const std::array<float, 3>& d = record.direction;
  const float length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  return d[0] / length != d[0] || d[1] / length != d[1] || d[2] / length != d[2];
}

bool hasNearZeroComponent(const RayRecord& record, float epsilon) {
  const std::array<float, 3>& d = record.direction;
  const float largest = std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
  return std::any_of(d.begin(), d.end(), [&](float c) { return std::abs(c) < epsilon * largest; });
}

Ray asRay(const RayRecord& record) {
  return Ray{{record.origin[0], record.origin[1], record.origin[2]},
             {record.direction[0], record.direction[1], record.direction[2]}};
}

glm::dvec3 place(const ModelPlacement& placement, const glm::dvec3& p) {
  return placement.rotation * (placement.scale * p) + placement.translation;
}

// The camera that sees the placed model as `camera` sees the unplaced one (uniform scale).
Camera placeCamera(Camera camera, const ModelPlacement& placement) {
  camera.position = place(placement, camera.position);
  camera.lookAt = place(placement, camera.lookAt);
  camera.up = placement.rotation * camera.up;
  return camera;
}

struct FrameComparison {
  size_t rays = 0, sameHit = 0, bothHit = 0;
  double maxTError = 0.0;  // |t_placed - expected|, world units
};

// `expectedT(i, tReference)` is what the placed model's t should be for ray i.
template <class ExpectedT>
FrameComparison compareFrames(const std::vector<TraversalResult>& reference,
                              const std::vector<TraversalResult>& placed, const FixedFormat& format,
                              ExpectedT expectedT) {
  FrameComparison comparison;
  comparison.rays = reference.size();
  for (size_t i = 0; i < reference.size(); ++i) {
    if (reference[i].hit != placed[i].hit) continue;
    ++comparison.sameHit;
    if (!reference[i].hit) continue;
    ++comparison.bothHit;
    const double expected = expectedT(i, format.toDouble(reference[i].tHit));
    comparison.maxTError =
        std::max(comparison.maxTError, std::abs(format.toDouble(placed[i].tHit) - expected));
  }
  return comparison;
}

}  // namespace

TEST_CASE("Ray records round-trip through files in their layout", "[rays]") {
  const std::vector<RayRecord> records = makeFrameRayRecords(smallCamera(8, 5), 1234);
  const std::string path = tempPath("rays.bin");
  writeRayBuffer(path, records);
  REQUIRE(std::filesystem::file_size(path) == records.size() * 32);
  const std::vector<uint32_t> words = encodeRayRecords(records);
  REQUIRE(words[8 * 13] == 13);  // id = x + y * width, bits 31:28 zero
  REQUIRE(bitsToFloat(words[8 * 13 + 1]) == static_cast<float>(Camera{}.position.x));
  REQUIRE(bitsToFloat(words[8 * 13 + 6]) == records[13].direction[2]);
  REQUIRE(words[8 * 13 + 7] == 1234);
  const std::array<float, 3>& d = records[13].direction;
  REQUIRE(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) == Approx(1.0f).epsilon(1e-6));

  const std::vector<RayRecord> back = readRayBuffer(path);
  REQUIRE(back.size() == records.size());
  for (size_t i = 0; i < records.size(); ++i) {
    REQUIRE(back[i].id == records[i].id);
    REQUIRE(back[i].origin == records[i].origin);
    REQUIRE(back[i].direction == records[i].direction);
    REQUIRE(back[i].modelAddress == records[i].modelAddress);
  }
}

TEST_CASE("Malformed ray records are rejected with the record and the reason", "[rays]") {
  std::vector<uint32_t> words = rayWords();
  words[8 * 2] |= 0x10000000u;
  REQUIRE_THROWS_WITH(decodeRayRecords(words),
                      Catch::Contains("record 2") && Catch::Contains("bits 31:28"));
  words = rayWords();
  words[8 * 1 + 5] = 0x7FC00000u;  // NaN dy
  REQUIRE_THROWS_WITH(decodeRayRecords(words), Catch::Contains("record 1") &&
                                                   Catch::Contains("direction y is not a finite"));
  words = rayWords();
  words[8 * 3 + 1] = 0xFF800000u;  // -inf ox
  REQUIRE_THROWS_WITH(decodeRayRecords(words), Catch::Contains("origin x is not a finite"));
  words = rayWords();
  words[8 * 3 + 3] = floatBits(0x1p65f);
  REQUIRE_THROWS_WITH(decodeRayRecords(words), Catch::Contains("origin z is beyond 2^64"));
  words = rayWords();
  words[8 * 0 + 4] = 0;
  words[8 * 0 + 5] = 0x80000000u;  // -0
  words[8 * 0 + 6] = 0;
  REQUIRE_THROWS_WITH(decodeRayRecords(words),
                      Catch::Contains("record 0") && Catch::Contains("direction is zero"));
  words.pop_back();
  REQUIRE_THROWS_WITH(decodeRayRecords(words), Catch::Contains("not a multiple of 8"));

  RayRecord tooLarge;
  tooLarge.id = TValueRecord::kMaxId + 1;
  REQUIRE_THROWS_AS(encodeRayRecords({RayRecord{}, tooLarge}), std::invalid_argument);
  REQUIRE_THROWS_WITH(encodeRayRecords({RayRecord{}, tooLarge}), Catch::Contains("ray record 1"));
  const std::string path = tempPath("short_rays.bin");
  std::ofstream(path, std::ios::binary) << std::string(40, '\0');
  REQUIRE_THROWS_WITH(readRayBuffer(path),
                      Catch::Contains("ray buffer") && Catch::Contains("40 bytes"));
}

TEST_CASE("Model headers round-trip and place the model as documented", "[rays]") {
  ModelPlacement placement;
  placement.translation = {1.5, -2.0, 0.25};
  placement.rotation = rotationFromEulerDegrees({0.0, 0.0, 90.0});
  placement.scale = {2.0, 4.0, 0.5};
  const glm::dvec3 x = placement.rotation * glm::dvec3(1.0, 0.0, 0.0);
  REQUIRE(x.y == Approx(1.0));  // 90 degrees about z: x to y
  const glm::dmat3 xThenY = rotationFromEulerDegrees({90.0, 90.0, 0.0});
  const glm::dvec3 y = xThenY * glm::dvec3(0.0, 1.0, 0.0);  // x: y to z, then y: z to x
  REQUIRE(y.x == Approx(1.0));

  const ModelHeader header = makeModelHeader(placement, 77);
  const ModelHeaderWords words = encodeModelHeader(header);
  REQUIRE(bitsToFloat(words[0]) == 1.5f);
  REQUIRE(bitsToFloat(words[4]) == Approx(1.0f));  // R^T row 0, column 1 = R[1][0] = sin 90
  REQUIRE(bitsToFloat(words[12]) == 0.5f);
  REQUIRE(bitsToFloat(words[13]) == 0.25f);
  REQUIRE(bitsToFloat(words[14]) == 2.0f);
  REQUIRE(words[15] == 77);
  const ModelHeader back = decodeModelHeader(words);
  REQUIRE(encodeModelHeader(back) == words);

  SvoImage image{std::vector<uint32_t>(100, 0), 3};
  const uint32_t address = appendModelHeader(image, placement);
  REQUIRE(address == 100);
  REQUIRE(image.words.size() == 100 + kModelHeaderWords);
  const ModelHeader read = readModelHeader(image.memory(), address);
  REQUIRE(read.root == 3);
  REQUIRE(read.inverseRotation == header.inverseRotation);
}

TEST_CASE("Malformed model headers are rejected with the address and the field", "[rays]") {
  SvoImage image{std::vector<uint32_t>(20, 0), 0};
  const uint32_t address = appendModelHeader(image, ModelPlacement{});
  const WordMemory memory = image.memory();
  REQUIRE_THROWS_WITH(readModelHeader(memory, 21),
                      Catch::Contains("word 21") && Catch::Contains("past the end"));
  REQUIRE_THROWS_WITH(readModelHeader(memory, 1u << 31), Catch::Contains("past the end"));

  auto corrupted = [&](size_t word, uint32_t value) {
    std::vector<uint32_t> words = image.words;
    words[address + word] = value;
    return words;
  };
  auto readFrom = [&](const std::vector<uint32_t>& words) {
    return readModelHeader(WordMemory(words), address);
  };
  REQUIRE_THROWS_WITH(readFrom(corrupted(1, 0x7FC00000u)),
                      Catch::Contains("word 20") &&
                          Catch::Contains("translation y is not a finite"));
  REQUIRE_THROWS_WITH(readFrom(corrupted(2, floatBits(-0x1p70f))),
                      Catch::Contains("translation z is beyond 2^64"));
  REQUIRE_THROWS_WITH(readFrom(corrupted(12, 0)), Catch::Contains("inverse scale x is 0"));
  REQUIRE_THROWS_WITH(readFrom(corrupted(13, floatBits(-1.0f))),
                      Catch::Contains("inverse scale y is -1"));
  REQUIRE_THROWS_WITH(readFrom(corrupted(14, 0x7F800000u)),
                      Catch::Contains("inverse scale z is not a finite"));
  REQUIRE_THROWS_WITH(readFrom(corrupted(4, floatBits(0.5f))), Catch::Contains("not orthonormal"));
  REQUIRE_THROWS_WITH(readFrom(corrupted(3, floatBits(-1.0f))), Catch::Contains("reflection"));
  REQUIRE_THROWS_WITH(readFrom(corrupted(15, 36)),
                      Catch::Contains("root address 36 is outside the memory"));

  ModelPlacement placement;
  placement.scale = {1.0, 0.0, 1.0};
  REQUIRE_THROWS_AS(makeModelHeader(placement, 0), std::invalid_argument);
  REQUIRE_THROWS_WITH(makeModelHeader(placement, 0), Catch::Contains("scale y is 0"));
  placement.scale = {1.0, 1.0, 1e12};
  REQUIRE_THROWS_WITH(makeModelHeader(placement, 0), Catch::Contains("scale z is 1e+12"));
  placement.scale = glm::dvec3(1.0);
  placement.rotation[0][1] = 0.3;
  REQUIRE_THROWS_WITH(makeModelHeader(placement, 0), Catch::Contains("not orthonormal"));

  RayRecord ray;
  ray.modelAddress = 5;  // inside the tree's words: no valid header there
  const SvoBuild sphere = buildSvo(*makeProceduralScene("sphere", 3));
  REQUIRE_THROWS_WITH(rayRecordsToJobs(sphere.image.memory(), {RayRecord{}, ray}, 1e-4f),
                      Catch::Contains("ray record 0") && Catch::Contains("model header at word 0"));
}

TEST_CASE("The set-up follows eq. 6.6 step by step", "[rays]") {
  RayRecord record;
  record.id = 42;
  record.origin = {0.5f, -3.0f, 2.0f};
  record.direction = {0.0f, 2.0f, -4.0f};
  ModelHeader header;
  header.translation = {0.0f, -1.0f, 0.0f};
  header.inverseScale = {1.0f, 0.5f, 0.5f};
  header.root = 8;
  const TValueRecord job = rayRecordToJob(record, header, 1e-4f);
  // o' = (0.5, -1, 1), d' = (0, 1, -2): x replaced by 2e-4 (epsilon times the largest), z mirrored.
  REQUIRE(job.id == 42);
  REQUIRE(job.root == 8);
  REQUIRE(job.a == 0b100);
  const float rx = 1.0f / (1e-4f * 2.0f);
  REQUIRE(job.t0Bits[0] == floatBits(-0.5f * rx - rx));
  REQUIRE(job.t1Bits[0] == floatBits(-0.5f * rx + rx));
  REQUIRE(bitsToFloat(job.t0Bits[1]) == 0.0f);  // -(-1) * 1 - 1
  REQUIRE(bitsToFloat(job.t1Bits[1]) == 2.0f);
  REQUIRE(bitsToFloat(job.t0Bits[2]) == 0.0f);  // mirrored o'z = -1, r = 0.5: 0.5 - 0.5
  REQUIRE(bitsToFloat(job.t1Bits[2]) == 1.0f);

  // Doubling d halves every t exactly, the near-zero replacement included.
  RayRecord doubled = record;
  for (float& c : doubled.direction) c *= 2.0f;
  const TValueRecord half = rayRecordToJob(doubled, header, 1e-4f);
  for (int k = 0; k < 3; ++k) {
    REQUIRE(bitsToFloat(half.t0Bits[k]) == bitsToFloat(job.t0Bits[k]) / 2.0f);
    REQUIRE(bitsToFloat(half.t1Bits[k]) == bitsToFloat(job.t1Bits[k]) / 2.0f);
  }
  REQUIRE_THROWS_AS(rayRecordToJob(record, header, 0.0f), std::invalid_argument);
}

TEST_CASE("Extreme valid records and headers never give NaN or t0 > t1", "[rays]") {
  const float big = kMaxModelCoordinate;
  const float tiny = std::numeric_limits<float>::denorm_min();
  const std::vector<std::array<float, 3>> origins = {
      {big, -big, 0.0f}, {0.0f, 0.0f, 0.0f}, {-big, big, big}, {1.0f, -1.0f, 1.0f}};
  const std::vector<std::array<float, 3>> directions = {
      {tiny, 0.0f, -tiny}, {big, -big, tiny}, {0.0f, -1.0f, 0.0f}, {-tiny, big, 0.0f}};
  std::vector<ModelHeader> headers(3);
  headers[1].translation = {-big, big, -big};
  headers[1].inverseScale = {kMaxInverseScale, kMaxInverseScale, kMinInverseScale};
  headers[2].inverseScale = {kMinInverseScale, kMinInverseScale, kMaxInverseScale};
  ModelPlacement turned;
  turned.rotation = rotationFromEulerDegrees({33.0, -71.0, 12.0});
  headers[2].inverseRotation = makeModelHeader(turned, 0).inverseRotation;
  for (const ModelHeader& header : headers) {
    header.validate();
    for (const auto& origin : origins)
      for (const auto& direction : directions) {
        RayRecord record;
        record.origin = origin;
        record.direction = direction;
        record.validate();
        const TValueRecord job = rayRecordToJob(record, header, 1e-4f);
        for (int k = 0; k < 3; ++k) {
          const float t0 = bitsToFloat(job.t0Bits[k]);
          const float t1 = bitsToFloat(job.t1Bits[k]);
          REQUIRE_FALSE(std::isnan(t0));
          REQUIRE_FALSE(std::isnan(t1));
          REQUIRE(t0 <= t1);
        }
        REQUIRE_NOTHROW(decodeJobRecords(encodeJobRecords({job})));
      }
  }
}

TEST_CASE("With an identity header, ray records give the driver's t-values", "[rays]") {
  // Not bit-identical: the driver divides, t = (-1 - o) / d (two roundings, the subtraction often
  // exact), where the job manager takes the reciprocal and multiply-accumulates, t = -o r -+ r with
  // r = 1/d (three roundings). Where -o r and r nearly cancel (origin close to a face plane) the
  // result has few significant bits, so the distance is measured in ulps of the largest magnitude
  // among -o r, r and t. The driver also renormalises the direction in float; where that moves d
  // by an ulp the set-ups differ by one more.
  const float epsilon = static_cast<float>(kDefaultDirectionEpsilon);
  for (const glm::dvec3& position : {glm::dvec3(-1.9, 1.3, -2.6), glm::dvec3(0.3, 0.2, -3.0),
                                     glm::dvec3(2.5, -2.0, 1.5), glm::dvec3(0.999, 0.5, -4.0)}) {
    Camera camera = smallCamera(96, 72);
    camera.position = position;
    double worstSameDirection = 0.0, worst = 0.0;
    for (const RayRecord& record : makeFrameRayRecords(camera, 0)) {
      if (hasNearZeroComponent(record, epsilon)) continue;  // replaced differently: see below
      const TValueRecord job = rayRecordToJob(record, ModelHeader{}, epsilon);
      const TValueRecord driver = makeTValueRecord(record.id, asRay(record), 0);
      REQUIRE(job.a == driver.a);
      for (int k = 0; k < 3; ++k) {
        const float r = 1.0f / std::abs(record.direction[k]);
        const float p = (driver.a >> k & 1 ? record.origin[k] : -record.origin[k]) * r;
        for (const auto& [mine, theirs] : {std::pair{job.t0Bits[k], driver.t0Bits[k]},
                                           std::pair{job.t1Bits[k], driver.t1Bits[k]}}) {
          const float scale = std::max({std::abs(p), r, std::abs(bitsToFloat(theirs))});
          const double ulps = ulpsAt(bitsToFloat(mine), bitsToFloat(theirs), scale);
          worst = std::max(worst, ulps);
          if (!driverRenormalises(record)) worstSameDirection = std::max(worstSameDirection, ulps);
        }
      }
    }
    INFO("camera at " << position.x << "," << position.y << "," << position.z);
    CHECK(worstSameDirection <= 2.0);
    CHECK(worst <= 3.0);
  }
}

TEST_CASE("With an identity header, the golden model gives the driver's results", "[rays]") {
  const Camera camera = smallCamera(96, 72);
  for (const char* scene : {"sphere", "menger", "terrain"}) {
    const PlacedModel model = placedModel(scene, ModelPlacement{});
    GoldenModel golden(model.image.memory(), GoldenConfig{});
    const std::vector<TraversalResult> driver = golden.traceAll(makeFrameJobs(camera, 0));
    const std::vector<TraversalResult> rays =
        golden.traceRays(makeFrameRayRecords(camera, model.header), 1e-4f);
    const FixedFormat& format = golden.config().format;
    const FrameComparison comparison =
        compareFrames(driver, rays, format, [](size_t, double t) { return t; });
    INFO(scene << ": " << comparison.sameHit << " of " << comparison.rays << " agree, max |dt| "
               << comparison.maxTError);
    CHECK(comparison.bothHit > comparison.rays / 10);
    CHECK(comparison.sameHit == comparison.rays);
    CHECK(comparison.maxTError <= 4.0 / format.one());
    for (size_t i = 0; i < rays.size(); ++i) REQUIRE(rays[i].id() == i);
  }
}

TEST_CASE("Rays along the axes hit as with the driver's set-up", "[rays]") {
  const PlacedModel model = placedModel("sphere", ModelPlacement{});
  GoldenModel golden(model.image.memory(), GoldenConfig{});
  const glm::dvec3 axes[] = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {-1, 0, 0}};
  for (const glm::dvec3& axis : axes) {
    const Ray ray{-3.0 * axis + glm::dvec3(0.01, 0.02, 0.03), axis};
    const TraversalResult driver = golden.trace(makeTValueRecord(0, ray, 0));
    const TraversalResult mine = golden.traceRays({makeRayRecord(0, ray, model.header)}, 1e-4f)[0];
    REQUIRE(driver.hit);
    REQUIRE(mine.hit);
    REQUIRE(std::abs(mine.tHit - driver.tHit) <= 4);
    REQUIRE(mine.normal == driver.normal);
  }
}

TEST_CASE("A moved, rotated and uniformly scaled model looks the same from a moved camera",
          "[rays]") {
  ModelPlacement placement;
  placement.translation = {0.7, -0.4, 1.3};
  placement.rotation = rotationFromEulerDegrees({30.0, -20.0, 45.0});
  placement.scale = glm::dvec3(1.75);
  const Camera camera = smallCamera(96, 72);
  for (const char* scene : {"menger", "terrain"}) {
    const PlacedModel reference = placedModel(scene, ModelPlacement{});
    const PlacedModel moved = placedModel(scene, placement);
    GoldenModel referenceModel(reference.image.memory(), GoldenConfig{});
    GoldenModel movedModel(moved.image.memory(), GoldenConfig{});
    const std::vector<TraversalResult> expected =
        referenceModel.traceRays(makeFrameRayRecords(camera, reference.header), 1e-4f);
    const std::vector<TraversalResult> placed = movedModel.traceRays(
        makeFrameRayRecords(placeCamera(camera, placement), moved.header), 1e-4f);
    const FixedFormat& format = movedModel.config().format;
    const FrameComparison comparison = compareFrames(
        expected, placed, format, [&](size_t, double t) { return placement.scale.x * t; });
    INFO(scene << ": " << comparison.sameHit << " of " << comparison.rays << " agree, max |dt| "
               << comparison.maxTError);
    CHECK(comparison.bothHit > comparison.rays / 10);
    CHECK(comparison.sameHit >= 0.995 * comparison.rays);
    // Each side rounds t to the fixed-point grid: a few LSB, scaled on the placed side.
    CHECK(comparison.maxTError <= 4.0 * (1.0 + placement.scale.x) / format.one());
  }
}

TEST_CASE("A non-uniformly scaled model gives the hits of the rays mapped into it", "[rays]") {
  // World rays are the model-space rays mapped by the placement; t along a unit world direction is
  // the model-space t times |S u| for the unit model direction u.
  ModelPlacement placement;
  placement.translation = {-2.0, 0.5, 3.0};
  placement.rotation = rotationFromEulerDegrees({10.0, 70.0, -35.0});
  placement.scale = {1.5, 0.6, 1.1};
  const PlacedModel identity = placedModel("terrain", ModelPlacement{});
  const PlacedModel moved = placedModel("terrain", placement);
  const std::vector<Ray> modelRays = frameRays(smallCamera(96, 72));
  std::vector<RayRecord> reference, world;
  std::vector<double> stretch;
  for (size_t i = 0; i < modelRays.size(); ++i) {
    const auto id = static_cast<uint32_t>(i);
    const Ray& ray = modelRays[i];
    const glm::dvec3 u = glm::normalize(ray.direction);
    const Ray mapped{place(placement, ray.origin), placement.rotation * (placement.scale * u)};
    reference.push_back(makeRayRecord(id, ray, identity.header));
    world.push_back(makeRayRecord(id, mapped, moved.header));
    stretch.push_back(glm::length(placement.scale * u));
  }
  GoldenModel referenceModel(identity.image.memory(), GoldenConfig{});
  GoldenModel movedModel(moved.image.memory(), GoldenConfig{});
  const FrameComparison comparison =
      compareFrames(referenceModel.traceRays(reference, 1e-4f), movedModel.traceRays(world, 1e-4f),
                    movedModel.config().format, [&](size_t i, double t) { return stretch[i] * t; });
  INFO(comparison.sameHit << " of " << comparison.rays << " agree, max |dt| "
                          << comparison.maxTError);
  CHECK(comparison.bothHit > comparison.rays / 10);
  CHECK(comparison.sameHit >= 0.995 * comparison.rays);
  const double maxStretch = *std::max_element(stretch.begin(), stretch.end());
  CHECK(comparison.maxTError <= 4.0 * (1.0 + maxStretch) / movedModel.config().format.one());
}
