#pragma once
// The timed model of seed 001's ray pipe (raypipe_timed.h): the top as a class, each unit group's
// cycle function in its own file (timed_front.cpp, timed_traversal.cpp, timed_shortstack.cpp,
// timed_intersection.cpp, timed_list.cpp, timed_shader_return.cpp). A cycle visits the groups
// from the pixel buffer back to the PRG, as the RTL's combinational stalls settle; inside a group
// a unit does nothing unless it holds or is offered an item, and every FIFO, pipe and register is
// lazy in time, so no end-of-cycle tick is needed. A group is called only in the cycles the wake
// calendar (wake_calendar.h) books it for: a FIFO's head shown, a pipe's head leaving, a register
// valid, an arbiter holding an item, the PRG's v0; a group not called computes nothing and its
// stalls are low (each is some valid signal of its channels ANDed with more, and a valid one books
// the group).

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "kinds/kd/kd_image.h"
#include "raypipe/raypipe_config.h"
#include "raypipe/raypipe_run.h"
#include "sim/raypipe/pipe_trace.h"
#include "sim/raypipe/timed_units.h"
#include "sim/raypipe/vga_window.h"
#include "sim/raypipe/wake_calendar.h"

namespace rtu {
namespace raypipe_timed {

class TimedPipe {
 public:
  // With `trace`, every unit's transfers and stalls and every FIFO's count go to it (pipe_trace.h).
  TimedPipe(const RaypipeConfig& config, const KdImage& image,
            const std::vector<RaypipeCycleRay>& rays, const RaypipeCycleOptions& options,
            CycleTrace* trace = nullptr);
  RaypipeCycleRun run();

 private:
  RayRecord& record(uint32_t ray) { return records_[ray]; }
  StackRow& stackRow(uint32_t ray, uint32_t row) {
    return stack_[ray * static_cast<uint32_t>(config_.shortStackDepth) + row];
  }
  void busy(Unit u, const RayToken& t, bool hasRay = true);
  [[gnu::noinline, gnu::cold]] void recordTransfer(Unit u, const RayToken& t, bool hasRay);
  void stall(Unit u) { stalls(u, now_, now_ + 1); }
  // `u` stalled in every cycle of [from, to) (the PRG's group adds up some it was not called in).
  void stalls(Unit u, int64_t from, int64_t to) {
    if (to <= from) return;
    stall_[static_cast<size_t>(u)] += to - from;
    if (trace_) trace_->stalled(u, from, to);
  }
  // `inputs` of a unit with several (the shortstack's read FIFOs) stalled in this cycle: each
  // counts, the trace shows the cycle's stall once.
  void stalledInputs(Unit u, int inputs) {
    if (inputs == 0) return;
    stall_[static_cast<size_t>(u)] += inputs;
    if (trace_) trace_->stalled(u, now_, now_ + 1);
  }
  void traceTo(CycleTrace& trace);
  // The first cycle a record can still be made for: the one after the PRG group's last call while
  // its next call can add up stalls since then (a ray in the PRG's FIFO, or the PRG blocked).
  int64_t safeCycle() const {
    return c_.prgFifo.any() || prgBlocked_ ? std::min(now_, lastPrgCall_ + 1) : now_;
  }

  // The unit groups, as calendar bits, in the order a cycle visits them.
  enum Group : uint32_t {
    kShader = 1,
    kList = 2,
    kInt = 4,
    kTrav = 8,
    kStack = 16,
    kSint = 32,
    kPrg = 64
  };
  void wireCalendar();
  void settle(uint32_t group);
  bool runs(uint32_t group) const { return (booked_ & group) != 0; }

  void step();
  void shaderReturn();
  void listUnit();
  void listRecord(bool dsStall);
  void intersection();
  void traversal();
  std::array<bool, 2> leafMaxStalls();
  void travDecision(TravUnit& u, int i, bool toTarbStall);
  void travMath(TravUnit& u, int i, bool pipeDsStall, bool toListStall);
  bool travInput(TravUnit& u, bool rs0UsStall);
  void travLeaves(TravUnit& u, bool toLarbStall, bool toListStall);
  void travCache(TravUnit& u, int i, bool tcToTravStall);
  void shortStack();
  void shortStackInputs();
  void stackPath();
  void restartPath();
  void restartWrites(bool restReading);
  void stackWrites(bool reading, uint32_t readRow);
  void sceneIntersection();
  void shaderIssueAndPrg();
  bool travToSsStall(size_t i);
  bool listToSsStall();

  const RaypipeConfig& config_;
  bool recordTransfers_ = false;
  int64_t cyclesSinceReset_ = 0;  // the caches' way choice counts from reset
  int64_t initEnd_ = 0;           // the first cycle after the shader's is_init
  WordMemory memory_;
  KdSections sections_;
  const std::vector<RaypipeCycleRay>& rays_;
  Channels c_;
  WakeCalendar calendar_;
  uint32_t booked_ = 0;  // the groups booked for now_
  std::vector<RayRecord> records_;
  std::vector<StackRow> stack_;
  std::vector<RaypipeCycleResult> results_;
  std::vector<RaypipeTransfer> transfers_;
  std::vector<int64_t> busy_, stall_;
  std::unique_ptr<PipeTrace> trace_;
  int64_t now_ = 0, lastProgress_ = 0, lastWrite_ = -1;
  bool vgaReadWindow_ = false;  // the writer waits out the VGA reader (vga_window.h)
  VgaWindow vga_{0};
  int64_t writerWaits_ = 0;
  int64_t lastPrgCall_ = -1;  // the last cycle shaderIssueAndPrg ran
  bool prgBlocked_ = false;   // since then, the PRG stalls on every v0 (settle)
  size_t issued_ = 0, written_ = 0;
  int inFlight_ = 0, maxInFlight_ = 0;
  int64_t staleListHits_ = 0;
  // The stalls every group reads, from registered state at the cycle's start or from a group
  // visited earlier in the cycle.
  std::array<bool, 2> travToSsStall_{};  // per traversal unit
  bool listToSsStall_ = false, sintToSsStall_ = false;
  bool listToRsStall_ = false, intToListStall_ = false, sintUsStall_ = false;
};

}  // namespace raypipe_timed
}  // namespace rtu
