#include "app/triangle_replay.h"

#include <stdexcept>

#include "app/image_files.h"
#include "base/binary_file.h"
#include "rtu/model_header.h"

namespace rtu {

namespace {

// `rays` aimed at the identity model header at word `model` after an image file: each must name
// model address 0, or a std::runtime_error names `raysPath` and the record.
std::vector<RayRecord> recordsAtModel(const std::vector<RayRecord>& rays, uint32_t model,
                                      const std::string& raysPath) {
  std::vector<RayRecord> aimed = rays;
  for (size_t i = 0; i < aimed.size(); ++i) {
    if (aimed[i].modelAddress != 0)
      throw std::runtime_error("ray buffer '" + raysPath + "': record " + std::to_string(i) +
                               " names model address " + std::to_string(aimed[i].modelAddress) +
                               "; an image file has no model headers: give 0");
    aimed[i].modelAddress = model;
  }
  return aimed;
}

}  // namespace

TriangleReplayInput triangleReplayInput(const std::string& core, const std::string& imagePath,
                                        const std::vector<RayRecord>& rays,
                                        const std::string& raysPath) {
  if (imagePath.empty())
    throw std::invalid_argument("replay --core " + core + ": give the " + core +
                                " image to trace the ray records through (--accel-file)");
  const std::string kind = imageKindOf(readWordFile(imagePath, sizeof(uint32_t), "triangle image"));
  if (kind != core)
    throw std::invalid_argument(
        "--accel-file '" + imagePath + "' is " +
        (kind.empty() ? "no " + imageKindNames() + " image" : "a " + kind + " image") +
        ", and --core is " + core + ": give the image its core traces");
  TriangleReplayInput input;
  withImageKind(core,
                [&](auto image) { input.words = KindImageFile<decltype(image)>::read(imagePath); });
  const uint32_t model = appendModelHeader(input.words, ModelPlacement{}, 0);
  const std::vector<RayRecord> aimed = recordsAtModel(rays, model, raysPath);
  input.records.assign(aimed.begin(), aimed.end());
  return input;
}

std::vector<ResultRow> triangleResultRows(const std::string& core,
                                          const std::vector<CoreKindResult>& results,
                                          const std::vector<uint32_t>& words) {
  std::vector<ResultRow> rows;
  withImageKind(core,
                [&](auto image) { rows = KindImageFile<decltype(image)>::rows(results, words); });
  return rows;
}

}  // namespace rtu
