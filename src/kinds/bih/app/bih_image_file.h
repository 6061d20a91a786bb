#pragma once
// The bih kind's image as a file (app/kind_image_file.h): a BIH image, recognised by its header.

#include <string>
#include <vector>

#include "app/kind_image_file.h"
#include "kinds/bih/bih_kind.h"

namespace rtu {

template <>
struct KindImageFile<BihKind<>> {
  static constexpr bool kByHeader = true;
  static bool recognises(const std::vector<uint32_t>& words);
  static std::string describeValid(const std::string& path, const std::vector<uint32_t>& words);
  static std::vector<uint32_t> read(const std::string& path);
  static std::vector<ResultRow> rows(const std::vector<CoreKindResult>& results,
                                     const std::vector<uint32_t>& words);
  static std::string golden(const RunConfig& settings, const std::vector<RayRecord>& rays,
                            std::vector<ResultRow>& rows);
};

}  // namespace rtu
