#include "kinds/bih/app/bih_golden.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "app/triangle_replay.h"
#include "kinds/bih/bih_kind.h"
#include "rtu/golden_shell.h"
#include "rtu/model_header.h"

namespace rtu {

ResultRow bihResultRow(const BihResult& result, const FixedTriangleFormat& format) {
  if (!result.hit) return {result.idWord, false, 0, {}, {}, {}, {}};
  // The seed's u weighs x2 and its v x1 (fixed_kernels.h rtusimBarycentrics), at 2^(m-1+E).
  const int scale = format.m - 1 + format.E;
  return {result.idWord,
          true,
          result.distance,
          result.primitive,
          std::ldexp(static_cast<double>(result.v), -scale),
          std::ldexp(static_cast<double>(result.u), -scale),
          {}};
}

BihGoldenRun traceBihGolden(const std::vector<uint32_t>& image, const std::vector<RayRecord>& rays,
                            const std::string& raysPath) {
  // The identity model header after the image: world space is the grid.
  std::vector<uint32_t> words = image;
  const uint32_t model = appendModelHeader(words, ModelPlacement{}, 0);
  const FixedTriangleFormat format = decodeFormat(decodeBihHeader(image.data()).format);
  BihKind<>::Setup setup(WordMemory(words), JobManagerTiming{}, BihConfig{});
  GoldenShell<BihKind<>> shell(WordMemory(words), BihConfig{});
  BihGoldenRun run;
  run.rows.reserve(rays.size());
  const std::vector<RayRecord> aimed = recordsAtModel(rays, model, raysPath, "a .bih file");
  const auto start = std::chrono::steady_clock::now();
  for (const RayRecord& record : aimed) {
    const JobSetUp<BihJob> set = setup.setUp(record);
    BihResult result;
    shell.run(record.id, set.job, result);  // a ray that misses the box ends in AABB
    run.nodes += result.counts.nodes;
    run.triangleTests += result.counts.triangleTests;
    run.cost += result.cost;
    run.rows.push_back(bihResultRow(result, format));
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace rtu
