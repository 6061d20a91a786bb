#include "rtu/model_header.h"

#include <stdexcept>
#include <string>

#include "base/float_bits.h"

namespace rtu {

ModelHeader makeModelHeader(const ModelPlacement& placement, uint32_t root) {
  ModelHeader header;
  static_cast<ModelTransform&>(header) = makeModelTransform(placement);
  header.root = root;
  return header;
}

ModelHeaderWords encodeModelHeader(const ModelHeader& header) {
  ModelHeaderWords words{};
  for (int k = 0; k < 3; ++k) {
    words[k] = floatBits(header.translation[k]);
    words[12 + k] = floatBits(header.inverseScale[k]);
  }
  for (int i = 0; i < 9; ++i) words[3 + i] = floatBits(header.inverseRotation[i]);
  words[15] = header.root;
  return words;
}

ModelHeader decodeModelHeader(const ModelHeaderWords& words) {
  ModelHeader header;
  for (int k = 0; k < 3; ++k) {
    header.translation[k] = bitsToFloat(words[k]);
    header.inverseScale[k] = bitsToFloat(words[12 + k]);
  }
  for (int i = 0; i < 9; ++i) header.inverseRotation[i] = bitsToFloat(words[3 + i]);
  header.root = words[15];
  return header;
}

ModelHeader readModelHeader(const WordMemory& memory, uint32_t address) {
  const std::string where = "model header at word " + std::to_string(address);
  if (address > memory.size() || memory.size() - address < kModelHeaderWords)
    throw std::runtime_error(where + " runs past the end of the memory (" +
                             std::to_string(memory.size()) + " words)");
  ModelHeaderWords words;
  for (size_t i = 0; i < kModelHeaderWords; ++i)
    words[i] = memory.read(address + static_cast<uint32_t>(i));
  const ModelHeader header = decodeModelHeader(words);
  try {
    header.validate();
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(where + ": " + error.what());
  }
  if (header.root >= memory.size())
    throw std::runtime_error(where + ": root address " + std::to_string(header.root) +
                             " is outside the memory (" + std::to_string(memory.size()) +
                             " words)");
  return header;
}

uint32_t appendModelHeader(std::vector<uint32_t>& words, const ModelPlacement& placement,
                           uint32_t root) {
  const ModelHeaderWords header = encodeModelHeader(makeModelHeader(placement, root));
  const auto address = static_cast<uint32_t>(words.size());
  words.insert(words.end(), header.begin(), header.end());
  return address;
}

}  // namespace rtu
