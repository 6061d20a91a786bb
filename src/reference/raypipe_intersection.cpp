// The per-cycle reference of seed 001's ray pipe: larb, lcache, icache, raystore #1 and INT (R1
// RAYTRACER/int/int_unit.sv: the 45-cycle pipe, its list, larb and shadow FIFOs, the credit on
// their least free space).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "reference/raypipe_top.h"

namespace rtu {
namespace raypipe_ref {

// larb -> lcache -> icache -> raystore #1 -> INT (R1 RAYTRACER/int/int_unit.sv, int_math.sv;
// RAYTRACER/caches/simple_cache.sv or cache.sv, raystore/raystore_simple.sv).
void Pipe::intersection() {
  u_.larb.arbitrate(now_);
  if (const Flit* g = u_.larb.granted()) busy(Unit::Larb, *g);
  const int intInput = static_cast<int>(u_.trav.size());  // larb's last input
  if (u_.larb.accepted(intInput)) u_.intLarb.pop();
  // 256 - max(usedw of the list and larb FIFOs), or the shadow FIFO's free slots if fewer
  const int minLeft = std::min({u_.intList.numLeft(), u_.intLarb.numLeft(), u_.intShaderNumLeft});
  const bool intDsStall = u_.larb.stallUs(intInput) || intToListStall_;
  const bool intUsStall = u_.intPipe.usStall(intDsStall, minLeft);
  if (u_.intPipe.outValid(now_)) {
    const Flit& f = u_.intPipe.out(now_);
    if (f.found.hit || f.last) u_.intList.push(now_, f);
    if (!f.last) {
      Flit next = f;
      next.found = KdTriangleHit{};
      u_.intLarb.push(now_, next);
    }
  }
  const bool rsToIntValid = !u_.rs1.fifo.empty();
  const bool rsToIntStall = intUsStall && rsToIntValid;
  if (rsToIntValid) {
    if (rsToIntStall) {
      activity_.stall(Unit::Int);
    } else {
      Flit f = u_.rs1.fifo.front();
      u_.rs1.fifo.pop();
      Slot& s = slot(f.ray);
      UttmWords words{};
      const uint32_t base = sections_.uttms + f.tri * kKdUttmWords;
      for (int i = 0; i < kUttmWords; ++i) words[i] = memory_.read(base + i);
      f.found = intersectUnitTriangle(s.ray, unpackUttm(words), config_.division);
      ++s.counts.triangleTests;
      f.lnum -= 1;  // lnum_left - 1, lindex + 1 at entry
      f.lindex += 1;
      f.last = f.lnum == 0;
      u_.intPipe.accept(f);
      busy(Unit::Int, f);
    }
  }
  const bool rs1UsStall = u_.rs1.usStall(rsToIntStall);
  if (u_.rs1.pipe.outValid(now_)) u_.rs1.fifo.push(now_, u_.rs1.pipe.out(now_));
  // icache: its fifo's re = ~ds_stall; raystore #1 takes it unless stalling
  if (!u_.icache.fifo.empty() && !rs1UsStall) {
    u_.rs1.pipe.accept(u_.icache.fifo.front());
    u_.icache.fifo.pop();
  }
  const int64_t fromReset = cyclesSinceReset_;
  const bool icUsStall = u_.icache.cycle(now_, rs1UsStall, u_.dram, fromReset);
  Flit hit;
  if (u_.icache.exitHit(now_, hit)) u_.icache.fifo.push(now_, hit);
  if (!u_.lcache.fifo.empty()) {
    if (icUsStall) {
      u_.icache.refused();
    } else {
      u_.icache.accept(u_.lcache.fifo.front());
      u_.lcache.fifo.pop();
      busy(Unit::Icache, u_.lcache.fifo.front());
    }
  }
  const bool lcUsStall = u_.lcache.cycle(now_, icUsStall, u_.dram, fromReset);
  if (u_.lcache.exitHit(now_, hit)) {
    hit.tri = memory_.read(sections_.lists + hit.lindex);
    u_.lcache.fifo.push(now_, hit);
  }
  auto& larbOut = u_.larb.out();
  if (larbOut.valid(now_)) {
    if (lcUsStall) {
      activity_.stall(Unit::Lcache);
      u_.lcache.refused();
    } else {
      u_.lcache.accept(larbOut.front());
      larbOut.pop();
      busy(Unit::Lcache, larbOut.front());
    }
  }
}

}  // namespace raypipe_ref
}  // namespace rtu
