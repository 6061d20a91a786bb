#include "kinds/bih/app/bih_image_file.h"

#include <cmath>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "app/triangle_golden.h"
#include "kinds/bih/bih_file.h"
#include "kinds/bih/bih_validator.h"
#include "kinds/core_result.h"

namespace rtu {
namespace {

// A BIH result's row: t its distance along the record's direction, the seed's (v, u) as rtusim's
// barycentrics at the image's `format` (2^(m-1+E)); the seed's u weighs x2 and its v x1
// (fixed_kernels.h rtusimBarycentrics).
ResultRow bihRow(const BihResult& result, const FixedTriangleFormat& format) {
  if (!result.hit) return {result.idWord, false, 0, {}, {}, {}, {}};
  const int scale = format.m - 1 + format.E;
  return {result.idWord,
          true,
          result.distance,
          result.primitive,
          std::ldexp(static_cast<double>(result.v), -scale),
          std::ldexp(static_cast<double>(result.u), -scale),
          {}};
}

}  // namespace

bool KindImageFile<BihKind<>>::recognises(const std::vector<uint32_t>& words) {
  return looksLikeBihImage(words);
}

std::string KindImageFile<BihKind<>>::describeValid(const std::string& path,
                                                    const std::vector<uint32_t>& words) {
  const std::vector<ImageProblem> problems = validateBih(words);
  if (!problems.empty()) throw std::runtime_error(describeBihProblems("'" + path + "'", problems));
  const BihHeader header = decodeBihHeader(words.data());
  return "valid BIH image, " + std::to_string(header.nodeCount) + " nodes, " +
         std::to_string(header.listCount) + " list entries, " +
         std::to_string(header.triangleCount) + " triangles, " +
         std::to_string(words.size() * sizeof(uint32_t)) + " bytes";
}

// Warns of the seed's capacities the image exceeds (readBihFile).
std::vector<uint32_t> KindImageFile<BihKind<>>::read(const std::string& path) {
  BihImage image = readBihFile(path);
  for (const std::string& warning : image.warnings) std::cerr << "warning: " << warning << "\n";
  return std::move(image.words);
}

// The image's formats scale its barycentrics.
std::vector<ResultRow> KindImageFile<BihKind<>>::rows(const std::vector<CoreKindResult>& results,
                                                      const std::vector<uint32_t>& words) {
  const FixedTriangleFormat format = decodeFormat(decodeBihHeader(words.data()).format);
  std::vector<ResultRow> rows;
  rows.reserve(results.size());
  for (const BihResult& r : resultsOfKind<BihKind<>>(results)) rows.push_back(bihRow(r, format));
  return rows;
}

// The image on its grid: the records are grid coordinates (a .bih file keeps the scene box on the
// grid only, header words 11-13, not where the world lay), and the kind's job set-up clips each
// ray to [0, upper] and quantises it as for any world ray whose model header is the identity.
std::string KindImageFile<BihKind<>>::golden(const RunConfig& settings,
                                             const std::vector<RayRecord>& rays,
                                             std::vector<ResultRow>& rows) {
  return traceImageGolden<BihKind<>>(settings, rays, rows);
}

}  // namespace rtu
