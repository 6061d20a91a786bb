#pragma once
// Read-only view of a memory image: 32-bit words addressed by word index, as every core kind's
// images are laid out (an SVO's descriptors, later BVH nodes and triangles). Reads outside the
// image return 0, so a corrupt image cannot make a model read out of bounds.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rtu {

class WordMemory {
 public:
  WordMemory() = default;
  WordMemory(const uint32_t* words, size_t size) : words_(words), size_(size) {}
  explicit WordMemory(const std::vector<uint32_t>& words)
      : WordMemory(words.data(), words.size()) {}

  uint32_t read(uint32_t address) const { return address < size_ ? words_[address] : 0; }
  size_t size() const { return size_; }
  // The words themselves, for a component that grants direct access (the LT model's ROM).
  const uint32_t* data() const { return words_; }

 private:
  const uint32_t* words_ = nullptr;
  size_t size_ = 0;
};

}  // namespace rtu
