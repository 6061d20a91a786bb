#include "kinds/bvh/bvh_file.h"

#include <stdexcept>

#include "base/binary_file.h"
#include "kinds/bvh/bvh_validator.h"

namespace rtu {

bool looksLikeBvhImage(const std::vector<uint32_t>& words) {
  return !words.empty() && words[0] == kBvhMagic;
}

BvhImage readBvhFile(const std::string& path) {
  BvhImage image{readWordFile(path, sizeof(uint32_t), "BVH image")};
  const std::vector<BvhProblem> problems = validateBvh(image.words);
  if (!problems.empty())
    throw std::runtime_error(describeBvhProblems("BVH image '" + path + "'", problems));
  return image;
}

void writeBvhFile(const std::string& path, const BvhImage& image) {
  writeWordFile(path, image.words);
}

}  // namespace rtu
