#include "svo_image.h"

#include "binary_file.h"

namespace rtu {

SvoImage readSvoFile(const std::string& path, uint32_t root) {
  return SvoImage{readWordFile(path, sizeof(uint32_t), "SVO image"), root};
}

void writeSvoFile(const std::string& path, const SvoImage& image) {
  writeWordFile(path, image.words);
}

}  // namespace rtu
