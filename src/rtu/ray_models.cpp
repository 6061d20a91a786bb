#include "rtu/ray_models.h"

#include <stdexcept>

namespace rtu {

ImageEntry readImageEntry(const WordMemory& memory, uint32_t address, uint32_t alignWords,
                          uint32_t magic, uint32_t kind, const std::string& kindName) {
  ImageEntry entry;
  entry.model = readModelHeader(memory, address);
  const uint32_t root = entry.model.root;
  entry.where = "model header at word " + std::to_string(address) + ": " + kindName + " image at " +
                std::to_string(root);
  if (root % alignWords != 0)
    throw std::runtime_error(entry.where + " is not on a multiple of " +
                             std::to_string(alignWords) + " words");
  if (memory.size() - root < kImageHeaderWords)
    throw std::runtime_error(entry.where + " runs past the end of the memory (" +
                             std::to_string(memory.size()) + " words)");
  for (uint32_t i = 0; i < kImageHeaderWords; ++i) entry.header[i] = memory.read(root + i);
  if (entry.header[0] != magic || entry.header[1] != kind)
    throw std::runtime_error(entry.where + " is not a " + kindName + " image (magic " +
                             std::to_string(entry.header[0]) + ", kind " +
                             std::to_string(entry.header[1]) + ")");
  return entry;
}

}  // namespace rtu
