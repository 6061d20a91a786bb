#include "kinds/bih/app/bih_image_file.h"

#include <iostream>
#include <stdexcept>
#include <utility>

#include "app/golden_summary.h"
#include "kinds/bih/app/bih_golden.h"
#include "kinds/bih/bih_file.h"
#include "kinds/bih/bih_validator.h"
#include "kinds/core_result.h"

namespace rtu {

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

std::vector<uint32_t> KindImageFile<BihKind<>>::read(const std::string& path) {
  return readBihFile(path).words;
}

// The image's formats scale its barycentrics.
std::vector<ResultRow> KindImageFile<BihKind<>>::rows(const std::vector<CoreKindResult>& results,
                                                      const std::vector<uint32_t>& words) {
  const FixedTriangleFormat format = decodeFormat(decodeBihHeader(words.data()).format);
  std::vector<ResultRow> rows;
  rows.reserve(results.size());
  for (const BihResult& r : resultsOfKind<BihKind<>>(results))
    rows.push_back(bihResultRow(r, format));
  return rows;
}

// The image on its grid: the records are grid coordinates (bih_golden.h).
std::string KindImageFile<BihKind<>>::golden(const RunConfig& settings,
                                             const std::vector<RayRecord>& rays,
                                             std::vector<ResultRow>& rows) {
  const BihImage image = readBihFile(settings.accel.file);
  for (const std::string& warning : image.warnings) std::cerr << "warning: " << warning << "\n";
  BihGoldenRun run = traceBihGolden(image.words, rays, settings.rays);
  rows = std::move(run.rows);
  return triangleGoldenSummary(rows, run.cost, run.nodes, run.triangleTests, run.seconds);
}

}  // namespace rtu
