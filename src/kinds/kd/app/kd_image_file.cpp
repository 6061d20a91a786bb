#include "kinds/kd/app/kd_image_file.h"

#include <stdexcept>

#include "app/triangle_golden.h"
#include "base/binary_file.h"
#include "kinds/core_result.h"
#include "kinds/kd/kd_image.h"
#include "rtu/image_problems.h"

namespace rtu {
namespace {

// The seed's u weighs A (v0), its v B (v1): rtusim's (u, v) are (v, 1 - u - v).
ResultRow kdRow(const KdResult& r) {
  if (!r.hit) return {r.idWord, false, 0, {}, {}, {}, {}};
  return {r.idWord, true, r.t, r.primitive, r.v, 1.0 - r.u - r.v, {}};
}

void checkKdImage(const std::string& path, const std::vector<uint32_t>& words) {
  const std::vector<ImageProblem> problems = validateKd(words);
  if (!problems.empty())
    throw std::runtime_error(describeImageProblems("'" + path + "'", "k-d", problems, 10));
}

}  // namespace

bool KindImageFile<KdKind>::recognises(const std::vector<uint32_t>& words) {
  return !words.empty() && words[0] == kKdMagic;
}

std::string KindImageFile<KdKind>::describeValid(const std::string& path,
                                                 const std::vector<uint32_t>& words) {
  checkKdImage(path, words);
  const KdHeader header = decodeKdHeader(words.data());
  return "valid k-d image, " + std::to_string(header.nodeCount) + " nodes, " +
         std::to_string(header.listCount) + " list entries, " + std::to_string(header.uttmCount) +
         " triangles, " + std::to_string(words.size() * sizeof(uint32_t)) + " bytes";
}

std::vector<uint32_t> KindImageFile<KdKind>::read(const std::string& path) {
  std::vector<uint32_t> words = readWordFile(path, sizeof(uint32_t), "k-d image");
  checkKdImage(path, words);
  return words;
}

std::vector<ResultRow> KindImageFile<KdKind>::rows(const std::vector<CoreKindResult>& results,
                                                   const std::vector<uint32_t>&) {
  std::vector<ResultRow> rows;
  rows.reserve(results.size());
  for (const KdResult& r : resultsOfKind<KdKind>(results)) rows.push_back(kdRow(r));
  return rows;
}

std::string KindImageFile<KdKind>::golden(const RunConfig& settings,
                                          const std::vector<RayRecord>& rays,
                                          std::vector<ResultRow>& rows) {
  return traceImageGolden<KdKind>(settings, rays, rows);
}

}  // namespace rtu
