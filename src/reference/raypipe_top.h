#pragma once
// The per-cycle reference of seed 001's ray pipe: the top (raypipe_cycles.h) as a class, its units'
// cycle functions each in the file of its unit (raypipe_front.cpp, raypipe_traversal.cpp,
// raypipe_shortstack.cpp, raypipe_intersection.cpp, raypipe_list.cpp,
// raypipe_shader_return.cpp). Within a cycle the combinational stalls are evaluated from the pixel
// buffer back to the PRG, each after the stalls it depends on, as the RTL's always_comb blocks
// settle; every register, FIFO and pipe then takes its new state at the cycle's end (tick).

#include <algorithm>
#include <array>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/raypipe_cycles.h"
#include "reference/raypipe_units.h"
#include "reference/raypipe_vga.h"

namespace rtu {
namespace raypipe_ref {

class Pipe {
 public:
  Pipe(const RaypipeConfig& config, const KdImage& image, const std::vector<RaypipeCycleRay>& rays,
       const RaypipeCycleOptions& options)
      : config_(config),
        writer_(options.writer),
        recordTransfers_(options.recordTransfers),
        cyclesSinceReset_(options.cyclesSinceReset),
        memory_(image.memory()),
        sections_(sectionsOf(decodeKdHeader(image.words.data()))),
        rays_(rays),
        u_(config) {
    results_.resize(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) results_[i].pixelId = rays[i].pixelId;
    slots_.resize(static_cast<size_t>(config.raysInFlight));
    for (auto& slot : slots_) slot.stack.resize(static_cast<size_t>(config.shortStackDepth));
    // The shader's reset fill (is_init): ray id i written i cycles after reset; results blocked
    // for the 512 cycles of the fill.
    const int64_t reset = -std::min<int64_t>(options.cyclesSinceReset, 1000000);
    for (int id = 0; id < config.raysInFlight; ++id)
      u_.idFifo.preload(static_cast<uint32_t>(id), reset + id);
    initEnd_ = reset + 512;
    u_.dram.startAfter(options.cyclesSinceReset);
    // The reader's state repeats every screen: 521 lines of 800 25 MHz clocks, 480 x 1278 active
    // cycles (a multiple of the one-hot register's 4).
    if (writer_.vgaReadWindow)
      for (int64_t i = 0; i < writer_.vgaPhase % VgaReader::kScreenCycles; ++i) vga_.tick();
  }

  RaypipeCycleRun run() {
    const auto start = std::chrono::steady_clock::now();
    int64_t lastProgress = 0;
    size_t exited = 0, written = 0;
    while (written < rays_.size()) {
      const int64_t before = activity_.total();
      step(exited, written);
      if (activity_.total() != before) lastProgress = now_;
      if (now_ - lastProgress > 1000000)
        throw std::logic_error("raypipe reference: no progress for a million cycles at cycle " +
                               std::to_string(now_));
      ++now_;
    }
    RaypipeCycleRun run;
    run.setResults(results_);
    run.lastWriteCycle = lastWrite_;
    run.writerWaits = writerWaits_;
    run.transfers = std::move(transfers_);
    run.units = activity_.table();
    run.fifos = u_.fifoPeaks();
    run.maxRaysInFlight = maxInFlight_;
    run.staleListHits = staleListHits_;
    if (config_.cache == RaypipeCacheKind::SetAssociative) {
      run.caches = u_.cacheCounts();
      run.dram = u_.dram.counts();
    }
    run.hostSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return run;
  }

 private:
  Slot& slot(uint32_t ray) { return slots_[ray]; }

  void step(size_t& exited, size_t& written);
  void shaderReturn(size_t& exited, size_t& written);
  void listUnit();
  void intersection();
  void traversal();
  void travUnit(TravUnit& u, int i, bool toListStall);
  std::array<bool, 2> leafMaxStalls();
  void shortStack();
  void stackWrites(bool reading, uint32_t readRow);
  void sceneIntersection();
  void shaderIssueAndPrg();
  void tick();

  const RaypipeConfig& config_;
  RaypipePixelWriter writer_;
  bool recordTransfers_ = false;
  int64_t cyclesSinceReset_ = 0;  // the caches' way choice counts from reset
  int64_t initEnd_ = 0;           // the first cycle after the shader's is_init
  std::vector<RaypipeTransfer> transfers_;
  // A unit took `f` this cycle.
  void busy(Unit u, const Flit& f, bool hasRay = true) {
    activity_.busy(u);
    if (recordTransfers_)
      transfers_.push_back(
          RaypipeTransfer{now_, unitName(u), hasRay ? f.ray : RaypipeTransfer::kNoRayId, f.index});
  }
  VgaReader vga_;
  int64_t writerWaits_ = 0;
  WordMemory memory_;
  KdSections sections_;
  const std::vector<RaypipeCycleRay>& rays_;
  Units u_;
  std::vector<Slot> slots_;
  std::vector<RaypipeCycleResult> results_;
  Activity activity_;
  int64_t now_ = 0;
  int64_t lastWrite_ = -1;
  size_t issued_ = 0;  // pixels the PRG accepted
  int inFlight_ = 0, maxInFlight_ = 0;
  int64_t staleListHits_ = 0;
  // Stalls every unit reads, computed at the cycle's start from registered state.
  std::array<bool, 2> travToSsStall_{};  // per traversal unit
  bool listToSsStall_ = false, sintToSsStall_ = false;
  // The list unit reads leaf_max in the cycle after a leaf's last triangle entered it (it runs
  // before the traversal units in a cycle, so this cycle's entry is kept beside the last); with two
  // traversal units a write that meets that read and the other unit's write waits, the unit rrp
  // names (list_unit.sv).
  std::array<int64_t, 2> leafAccepts_{-2, -2};  // the list unit's last two leaf ends taken
  int leafMaxPointer_ = 0;
  bool listToRsStall_ = false, intToListStall_ = false, sintUsStall_ = false;
};

}  // namespace raypipe_ref
}  // namespace rtu
