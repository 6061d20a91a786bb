// The timed model of seed 001's ray pipe: larb, lcache, icache, raystore #1 and INT (int_unit.sv,
// int_math.sv; simple_cache.sv or cache.sv, raystore_simple.sv). Timing rules: larb as
// rotating_arbiter.h
// ([i] traversal unit i's leaf, then INT's next triangle); three 2-cycle reads in a row, each into
// a 3-entry FIFO; INT a 45-cycle pipe into the list FIFO (hits and last triangles) and the larb
// FIFO (all but the last), its credit their least free space (or the shadow FIFO's).
#include <algorithm>

#include "sim/raypipe/timed_pipe.h"

namespace rtu {
namespace raypipe_timed {

void TimedPipe::intersection() {
  const int units = static_cast<int>(c_.trav.size());  // INT is larb's last input
  RotatingArbiter<RayToken>::Offers offers{};
  bool any = c_.larb.holds();
  for (int i = 0; i < units; ++i) {
    Register& r = c_.trav[static_cast<size_t>(i)].travLarb;
    offers[static_cast<size_t>(i)] = r.valid(now_) ? &r.value(now_) : nullptr;
  }
  offers[static_cast<size_t>(units)] = c_.intLarb.shown(now_) ? &c_.intLarb.front() : nullptr;
  for (const RayToken* o : offers) any = any || o;
  if (any)
    if (const RayToken* g = c_.larb.arbitrate(now_, offers)[0]) busy(Unit::Larb, *g);
  if (c_.larb.accepted(units, now_)) c_.intLarb.pop(now_);
  const int minLeft =
      std::min({c_.intList.numLeft(now_), c_.intLarb.numLeft(now_), c_.intShaderNumLeft});
  const bool intDsStall = c_.larb.stallUs(units, now_) || intToListStall_;
  const bool intUsStall = c_.intPipe.usStall(now_, intDsStall, minLeft);
  if (c_.intPipe.exiting(now_)) {
    const RayToken t = c_.intPipe.take(now_);
    if (t.found.hit || t.last) c_.intList.push(now_, t);
    if (!t.last) {
      RayToken next = t;
      next.found = KdTriangleHit{};
      c_.intLarb.push(now_, next);
    }
  }
  const bool rsValid = c_.rs1.fifo.shown(now_);
  const bool rsToIntStall = intUsStall && rsValid;
  if (rsValid) {
    if (rsToIntStall) {
      stall(Unit::Int);
    } else {
      RayToken t = c_.rs1.fifo.pop(now_);
      RayRecord& r = record(t.ray);
      UttmWords words{};
      const uint32_t base = sections_.uttms + t.tri * kKdUttmWords;
      for (int i = 0; i < kUttmWords; ++i) words[static_cast<size_t>(i)] = memory_.read(base + i);
      t.found = intersectUnitTriangle(rays_[r.index].ray, unpackUttm(words), config_.division);
      ++r.counts.triangleTests;
      t.lnum -= 1;  // lnum_left - 1, lindex + 1 at entry
      t.lindex += 1;
      t.last = t.lnum == 0;
      c_.intPipe.accept(now_, t);
      busy(Unit::Int, t);
    }
  }
  // raystore #1 <- icache <- lcache <- larb's FIFO, each read moving on unless stalled
  const bool rs1UsStall = c_.rs1.usStall(now_, rsToIntStall);
  if (c_.rs1.pipe.exiting(now_)) c_.rs1.fifo.push(now_, c_.rs1.pipe.take(now_));
  if (c_.icache.read.fifo.shown(now_) && !rs1UsStall)
    c_.rs1.pipe.accept(now_, c_.icache.read.fifo.pop(now_));
  if (c_.icache.hitExiting(now_)) c_.icache.read.fifo.push(now_, c_.icache.takeHit(now_));
  const bool icUsStall = c_.icache.cycle(now_, rs1UsStall, cyclesSinceReset_);
  if (c_.lcache.read.fifo.shown(now_)) {
    if (icUsStall) {
      c_.icache.refused();
    } else {
      const RayToken t = c_.lcache.read.fifo.pop(now_);
      c_.icache.accept(now_, t);
      busy(Unit::Icache, t);
    }
  }
  if (c_.lcache.hitExiting(now_)) {
    RayToken t = c_.lcache.takeHit(now_);
    t.tri = memory_.read(sections_.lists + t.lindex);
    c_.lcache.read.fifo.push(now_, t);
  }
  const bool lcUsStall = c_.lcache.cycle(now_, icUsStall, cyclesSinceReset_);
  if (!c_.larb.out().shown(now_)) return;
  if (lcUsStall) {
    stall(Unit::Lcache);
    c_.lcache.refused();
    return;
  }
  const RayToken t = c_.larb.out().pop(now_);
  c_.lcache.accept(now_, t);
  busy(Unit::Lcache, t);
}

}  // namespace raypipe_timed
}  // namespace rtu
