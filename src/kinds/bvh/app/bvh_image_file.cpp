#include "kinds/bvh/app/bvh_image_file.h"

#include <stdexcept>

#include "app/triangle_golden.h"
#include "kinds/bvh/bvh_file.h"
#include "kinds/bvh/bvh_validator.h"
#include "kinds/core_result.h"

namespace rtu {
namespace {

ResultRow bvhRow(const BvhResult& r) {
  if (!r.hit) return {r.idWord, false, 0, {}, {}, {}, {}};
  return {r.idWord, true, r.t, r.primitive, r.u, r.v, {}};
}

}  // namespace

bool KindImageFile<BvhKind<>>::recognises(const std::vector<uint32_t>& words) {
  return looksLikeBvhImage(words);
}

std::string KindImageFile<BvhKind<>>::describeValid(const std::string& path,
                                                    const std::vector<uint32_t>& words) {
  const std::vector<BvhProblem> problems = validateBvh(words);
  if (!problems.empty()) throw std::runtime_error(describeBvhProblems("'" + path + "'", problems));
  const BvhHeader header = decodeHeader(words.data());
  return "valid BVH image, " + std::to_string(header.nodeCount) + " nodes, " +
         std::to_string(header.triangleCount) + " triangles, " +
         std::to_string(words.size() * sizeof(uint32_t)) + " bytes";
}

std::vector<uint32_t> KindImageFile<BvhKind<>>::read(const std::string& path) {
  return readBvhFile(path).words;
}

std::vector<ResultRow> KindImageFile<BvhKind<>>::rows(const std::vector<CoreKindResult>& results,
                                                      const std::vector<uint32_t>&) {
  std::vector<ResultRow> rows;
  rows.reserve(results.size());
  for (const BvhResult& r : resultsOfKind<BvhKind<>>(results)) rows.push_back(bvhRow(r));
  return rows;
}

std::string KindImageFile<BvhKind<>>::golden(const RunConfig& settings,
                                             const std::vector<RayRecord>& rays,
                                             std::vector<ResultRow>& rows) {
  return traceImageGolden<BvhKind<>>(settings, rays, rows);
}

}  // namespace rtu
