#pragma once
// The access-width contract every kind's behaviour keeps (rtu/core_kind.h): a state reads only
// when readsMemory() says so, and only words of the aligned kWordsPerRead-word access that holds
// memoryAddress(). Runs a started behaviour to its end under that check.

#include <catch2/catch.hpp>

#include <cstdint>

#include "rtu/word_memory.h"

namespace rtu {

// The words read from `memory` until `behaviour` is no longer busy.
template <class Behaviour>
int wordsReadWithinAccesses(Behaviour& behaviour, const WordMemory& memory) {
  constexpr uint32_t kAccessMask = ~(static_cast<uint32_t>(Behaviour::kWordsPerRead) - 1);
  int reads = 0;
  while (behaviour.busy()) {
    const uint32_t access = behaviour.memoryAddress() & kAccessMask;
    const bool reading = behaviour.readsMemory();
    behaviour.step([&](uint32_t address) {
      CHECK(reading);
      CHECK(address - access < static_cast<uint32_t>(Behaviour::kWordsPerRead));
      ++reads;
      return memory.read(address);
    });
  }
  return reads;
}

}  // namespace rtu
