#pragma once
// The word of one SVO child descriptor, for the tests' hand-built images (index = word address).

#include <cstdint>

#include "kinds/svo/svo_memory.h"

namespace rtu {

inline uint32_t descriptor(bool far, uint32_t pointer, uint8_t valid, uint8_t leaf) {
  return Descriptor::make(far, pointer, valid, leaf).word;
}

}  // namespace rtu
