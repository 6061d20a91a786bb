#include "app/triangle_replay.h"

#include <stdexcept>

#include "app/bih_golden.h"
#include "base/binary_file.h"
#include "kinds/bih/bih_file.h"
#include "kinds/bvh/bvh_file.h"
#include "kinds/core_result.h"
#include "kinds/kd/kd_image.h"
#include "rtu/image_problems.h"
#include "rtu/model_header.h"

namespace rtu {
namespace {

// The kind whose image `words` hold, by the header's magic word ("" for none of them).
std::string imageKind(const std::vector<uint32_t>& words) {
  if (looksLikeBvhImage(words)) return BvhKind<>::kName;
  if (looksLikeBihImage(words)) return BihKind<>::kName;
  if (!words.empty() && words[0] == kKdMagic) return KdKind::kName;
  return "";
}

// The image, validated as `validate` does.
std::vector<uint32_t> readImage(const std::string& core, const std::string& path) {
  if (core == BvhKind<>::kName) return readBvhFile(path).words;
  if (core == BihKind<>::kName) return readBihFile(path).words;
  std::vector<uint32_t> words = readWordFile(path, sizeof(uint32_t), "k-d image");
  const std::vector<ImageProblem> problems = validateKd(words);
  if (!problems.empty())
    throw std::runtime_error(describeImageProblems("'" + path + "'", "k-d", problems, 10));
  return words;
}

ResultRow triangleRow(const BvhResult& r) {
  if (!r.hit) return {r.idWord, false, 0, {}, {}, {}, {}};
  return {r.idWord, true, r.t, r.primitive, r.u, r.v, {}};
}

// The seed's u weighs A (v0), its v B (v1): rtusim's (u, v) are (v, 1 - u - v).
ResultRow kdRow(const KdResult& r) {
  if (!r.hit) return {r.idWord, false, 0, {}, {}, {}, {}};
  return {r.idWord, true, r.t, r.primitive, r.v, 1.0 - r.u - r.v, {}};
}

}  // namespace

TriangleReplayInput triangleReplayInput(const std::string& core, const std::string& imagePath,
                                        const std::vector<RayRecord>& rays,
                                        const std::string& raysPath) {
  if (imagePath.empty())
    throw std::invalid_argument("replay --core " + core + ": give the " + core +
                                " image to trace the ray records through (--accel-file)");
  const std::string kind = imageKind(readWordFile(imagePath, sizeof(uint32_t), "triangle image"));
  if (kind != core)
    throw std::invalid_argument(
        "--accel-file '" + imagePath + "' is " +
        (kind.empty() ? std::string("no BVH, BIH or k-d image") : "a " + kind + " image") +
        ", and --core is " + core + ": give the image its core traces");
  TriangleReplayInput input{readImage(core, imagePath), {}};
  const uint32_t model = appendModelHeader(input.words, ModelPlacement{}, 0);
  const std::vector<RayRecord> aimed = recordsAtModel(rays, model, raysPath, "an image file");
  input.records.assign(aimed.begin(), aimed.end());
  return input;
}

std::vector<RayRecord> recordsAtModel(const std::vector<RayRecord>& rays, uint32_t model,
                                      const std::string& raysPath, const std::string& what) {
  std::vector<RayRecord> aimed = rays;
  for (size_t i = 0; i < aimed.size(); ++i) {
    if (aimed[i].modelAddress != 0)
      throw std::runtime_error("ray buffer '" + raysPath + "': record " + std::to_string(i) +
                               " names model address " + std::to_string(aimed[i].modelAddress) +
                               "; " + what + " has no model headers: give 0");
    aimed[i].modelAddress = model;
  }
  return aimed;
}

std::vector<ResultRow> triangleResultRows(const std::string& core,
                                          const std::vector<CoreKindResult>& results,
                                          const std::vector<uint32_t>& words) {
  std::vector<ResultRow> rows;
  rows.reserve(results.size());
  if (core == BihKind<>::kName) {
    const FixedTriangleFormat format = decodeFormat(decodeBihHeader(words.data()).format);
    for (const BihResult& r : resultsOfKind<BihKind<>>(results))
      rows.push_back(bihResultRow(r, format));
  } else if (core == KdKind::kName) {
    for (const KdResult& r : resultsOfKind<KdKind>(results)) rows.push_back(kdRow(r));
  } else {
    for (const BvhResult& r : resultsOfKind<BvhKind<>>(results)) rows.push_back(triangleRow(r));
  }
  return rows;
}

}  // namespace rtu
