#include "kinds/svo/svo_image.h"

#include "base/binary_file.h"

namespace rtu {

uint32_t appendModelHeader(SvoImage& image, const ModelPlacement& placement) {
  return appendModelHeader(image.words, placement, image.root);
}

SvoImage readSvoFile(const std::string& path, uint32_t root) {
  return SvoImage{readWordFile(path, sizeof(uint32_t), "SVO image"), root};
}

void writeSvoFile(const std::string& path, const SvoImage& image) {
  writeWordFile(path, image.words);
}

}  // namespace rtu
