#pragma once
// Pacing of a host stream (the thesis' 64-bit AXI DMA moves 8 bytes per cycle: a record every 4
// cycles, as its Table 8.5 measures; docs/exploration.md).
// One 32-byte record crosses at most every 32 / bytesPerCycle cycles after the previous one; 0
// means unlimited (a record every cycle, the thesis configuration of the exactness claim). For
// tests, a seeded random pattern makes the link inactive in some cycles (back-pressure).

#include <cstdint>
#include <random>

namespace rtu {

constexpr uint64_t kHostRecordBytes = 32;  // 8 words (a kind's results may take more)

struct HostLinkConfig {
  double bytesPerCycle = 0.0;      // 0: unlimited
  double activeProbability = 1.0;  // chance the link can move a record in a given cycle
  uint64_t seed = 1;
  uint64_t recordBytes = kHostRecordBytes;  // what one record takes on the link
};

class HostLinkPacer {
 public:
  explicit HostLinkPacer(HostLinkConfig config);

  // The first cycle a record may cross after one crossed in `cycle`.
  uint64_t nextAllowed(uint64_t cycle);
  bool random() const { return config_.activeProbability < 1.0; }
  // Draws whether the link is active in a cycle (only when random()); one draw per cycle asked.
  bool drawActive();

 private:
  uint64_t slotStart(uint64_t records) const;

  HostLinkConfig config_;
  double slot_;                       // cycles a record takes on a paced link
  uint64_t restartCycle_ = 0;         // pacing runs from here ...
  uint64_t recordsSinceRestart_ = 0;  // ... with this many records crossed since
  uint64_t lastSlotStart_ = 0;        // slotStart(recordsSinceRestart_)
  std::mt19937_64 generator_;
};

void validate(const HostLinkConfig& config, const char* which);

}  // namespace rtu
