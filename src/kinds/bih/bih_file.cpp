#include "kinds/bih/bih_file.h"

#include <stdexcept>

#include "base/binary_file.h"
#include "kinds/bih/bih_validator.h"

namespace rtu {

bool looksLikeBihImage(const std::vector<uint32_t>& words) {
  return !words.empty() && words[0] == kBihMagic;
}

BihImage readBihFile(const std::string& path) {
  BihImage image{readWordFile(path, sizeof(uint32_t), "BIH image"), {}};
  const std::vector<ImageProblem> problems = validateBih(image.words);
  if (!problems.empty())
    throw std::runtime_error(describeBihProblems("BIH image '" + path + "'", problems));
  image.warnings = bihCapacityWarnings(decodeBihHeader(image.words.data()));
  return image;
}

void writeBihFile(const std::string& path, const BihImage& image) {
  writeWordFile(path, image.words);
}

}  // namespace rtu
