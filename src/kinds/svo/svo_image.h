#pragma once
// An SVO memory image (thesis section 4.2): 32-bit node descriptors with the root at `root`.
// File form (.svo): the raw words, little-endian, nothing else; the root address travels with
// the jobs that use it.

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/svo/svo_memory.h"
#include "rtu/model_header.h"

namespace rtu {

struct SvoImage {
  std::vector<uint32_t> words;
  uint32_t root = 0;

  WordMemory memory() const { return WordMemory(words); }
  size_t bytes() const { return words.size() * sizeof(uint32_t); }
};

// Appends the header of a model placed at `placement` whose tree is the image's (root = image.root)
// after the image's words, and returns its word address (the image's size before). Throws
// std::invalid_argument as makeModelHeader does.
uint32_t appendModelHeader(SvoImage& image, const ModelPlacement& placement);

// Throws std::runtime_error naming the file on I/O errors or a size that is not a whole number
// of words. The image is not validated here: see svo_validator.h.
SvoImage readSvoFile(const std::string& path, uint32_t root = 0);
void writeSvoFile(const std::string& path, const SvoImage& image);

}  // namespace rtu
