// The timed model of seed 001's ray pipe: tarb, tcache, TRAV and raystore #0 (trav_unit.sv: the
// leaf FIFO and its two registered outputs, the math pipe beside its FIFO, the decision and its
// two registered outputs; trav_math.sv; simple_cache.sv or cache.sv). Timing rules: tarb as
// rotating_arbiter.h; tcache and raystore #0 a 2-cycle read into a 3-entry FIFO; a leaf into the
// leaf FIFO, an interior node through raystore #0 and the 14-cycle math pipe; the decision reads
// its FIFO's head when every output it needs is free or not stalled.
#include <algorithm>
#include <stdexcept>

#include "sim/raypipe/timed_pipe.h"

namespace rtu {
namespace raypipe_timed {
namespace {

struct Decision {
  bool toSs = false, toTarb = false;
  RayToken ss, tarb;
};

// TRAV's decision over the plane test of the node at its FIFO's head (trav_unit.sv).
Decision decide(const RayToken& f, uint32_t depth) {
  const KdPlaneTest& p = f.plane;
  const bool lowEmpty = f.nodeData.lowEmpty, highEmpty = f.nodeData.highEmpty;
  const uint32_t low = f.node + 1, high = f.nodeData.high;
  Decision d;
  d.ss = f;
  d.ss.popReq = (p.onlyLow && lowEmpty) || (p.onlyHigh && highEmpty);
  d.ss.pushReq = !lowEmpty && !highEmpty && (p.lowThenHigh || p.highThenLow);
  d.ss.restReq = f.search && d.ss.pushReq;
  d.ss.maxsceneReq = f.search && ((p.lowThenHigh && highEmpty) || (p.highThenLow && lowEmpty));
  d.ss.pushNode = p.lowThenHigh ? high : low;
  d.toSs = d.ss.popReq || d.ss.pushReq || d.ss.restReq || d.ss.maxsceneReq;
  d.toTarb = !d.ss.popReq;
  d.tarb = f;
  const bool toLow = p.onlyLow || (p.lowThenHigh && !lowEmpty) || (p.highThenLow && highEmpty);
  d.tarb.node = toLow ? low : high;
  if ((p.lowThenHigh && !lowEmpty) || (p.highThenLow && !highEmpty)) {
    if (!p.onlyLow && !p.onlyHigh) d.tarb.tMax = p.tMid;
  } else if (!p.onlyLow && !p.onlyHigh) {
    d.tarb.tMin = p.tMid;
  }
  const bool push = d.ss.pushReq;
  d.tarb.wptr = push ? (f.wptr + 1) % depth : f.wptr;
  d.tarb.num = push ? std::min(f.num + 1, depth) : f.num;
  d.tarb.search = f.search && !push;
  return d;
}

}  // namespace

void TimedPipe::traversal() {
  const int units = static_cast<int>(c_.trav.size());
  RotatingArbiter<RayToken>::Offers offers{};
  offers[0] = c_.stackFifo.shown(now_) ? &c_.stackFifo.front() : nullptr;
  offers[1] = c_.notMissFifo.shown(now_) ? &c_.notMissFifo.front() : nullptr;
  for (int i = 0; i < units; ++i) {
    Register& r = c_.trav[static_cast<size_t>(i)].travTarb;
    offers[static_cast<size_t>(2 + i)] = r.valid(now_) ? &r.value(now_) : nullptr;
  }
  offers[static_cast<size_t>(2 + units)] = c_.sintTarb.shown(now_) ? &c_.sintTarb.front() : nullptr;
  bool any = c_.tarb.holds();
  for (const RayToken* o : offers) any = any || o;
  if (any)
    for (const RayToken* g : c_.tarb.arbitrate(now_, offers))
      if (g) busy(Unit::Tarb, *g);
  const std::array<bool, 2> toListStall = leafMaxStalls();
  for (int i = 0; i < units; ++i) {
    TravUnit& u = c_.trav[static_cast<size_t>(i)];
    const bool toTarbStall = c_.tarb.stallUs(2 + i, now_);
    travDecision(u, i, toTarbStall);
    const bool pipeDsStall = (u.travSs.valid(now_) && travToSsStall_[static_cast<size_t>(i)]) ||
                             (u.travTarb.valid(now_) && toTarbStall);
    travMath(u, i, pipeDsStall, toListStall[static_cast<size_t>(i)]);
  }
}

// The list unit's leaf_max RAM (list_unit.sv): port A is its own read in the cycle after a leaf's
// last triangle entered it, else unit 0's write; port B the other write. When both units write and
// the list reads, the unit the pointer rrp names waits (rrp 0: unit 1) and rrp turns.
std::array<bool, 2> TimedPipe::leafMaxStalls() {
  if (c_.trav.size() < 2) return {false, false};
  const bool read = c_.leafReads[0] == now_ - 1 || c_.leafReads[1] == now_ - 1;
  const bool contend = read && c_.trav[0].travList.valid(now_) && c_.trav[1].travList.valid(now_);
  if (!contend) return {false, false};
  const bool rrp = c_.leafMaxPointer != 0;
  c_.leafMaxPointer ^= 1;
  return {rrp, !rrp};
}

void TimedPipe::travDecision(TravUnit& u, int i, bool toTarbStall) {
  const bool toSsStall = travToSsStall_[static_cast<size_t>(i)];
  const bool ssHeld = u.travSs.valid(now_) && toSsStall;
  const bool tarbHeld = u.travTarb.valid(now_) && toTarbStall;
  if (!u.travFifo.shown(now_)) {
    if (u.travSs.valid(now_) && !ssHeld) u.travSs.set(now_, false, nullptr);
    if (u.travTarb.valid(now_) && !tarbHeld) u.travTarb.set(now_, false, nullptr);
    return;
  }
  const uint32_t depth = static_cast<uint32_t>(config_.shortStackDepth);
  const Decision d = decide(u.travFifo.front(), depth);
  bool re = true;
  if (d.toSs) re = re && !toSsStall;
  if (d.toTarb) re = re && !toTarbStall;
  if (!ssHeld) u.travSs.set(now_, d.toSs && re, &d.ss);
  if (!tarbHeld) u.travTarb.set(now_, d.toTarb && re, &d.tarb);
  if (!re) {
    stall(Unit::TravDecide);
    return;
  }
  RayRecord& r = record(d.ss.ray);
  if (d.ss.pushReq) {
    ++r.counts.pushes;
    if (d.ss.num == depth) ++r.counts.dropped;
  }
  u.travFifo.pop(now_);
  busy(Unit::TravDecide, d.ss);
}

// raystore #0 -> the math pipe (14) beside its FIFO; then TRAV's input and leaf outputs.
void TimedPipe::travMath(TravUnit& u, int i, bool pipeDsStall, bool toListStall) {
  const bool rsToTravStall = u.travPipe.usStall(now_, pipeDsStall, u.travFifo.numLeft(now_));
  if (u.travPipe.exiting(now_)) u.travFifo.push(now_, u.travPipe.take(now_));
  if (u.rs0.fifo.shown(now_)) {
    if (rsToTravStall) {
      stall(Unit::TravMath);
    } else {
      RayToken t = u.rs0.fifo.pop(now_);
      t.plane = planeTest(rays_[record(t.ray).index].ray, t.nodeData.axis,
                          bitsToFloat(t.nodeData.splitBits), t.tMin, t.tMax, config_.division);
      u.travPipe.accept(now_, t);
      busy(Unit::TravMath, t);
    }
  }
  const bool rs0UsStall = u.rs0.usStall(now_, rsToTravStall);
  if (u.rs0.pipe.exiting(now_)) u.rs0.fifo.push(now_, u.rs0.pipe.take(now_));
  const bool tcToTravStall = travInput(u, rs0UsStall);
  travLeaves(u, c_.larb.stallUs(i, now_), toListStall);
  travCache(u, i, tcToTravStall);
}

// TRAV's input from tcache: a leaf into the leaf FIFO, an interior node to raystore #0; returns
// its stall.
bool TimedPipe::travInput(TravUnit& u, bool rs0UsStall) {
  if (!u.tcache.read.fifo.shown(now_)) return false;
  const RayToken& f = u.tcache.read.fifo.front();
  const bool leaf = f.nodeData.leaf;
  if (leaf ? u.leafFifo.full(now_) : rs0UsStall) {
    stall(Unit::Trav);
    return true;
  }
  RayToken t = u.tcache.read.fifo.pop(now_);
  RayRecord& r = record(t.ray);
  ++r.counts.nodes;
  if (leaf) {
    ++r.counts.leaves;
    if (t.nodeData.count == 0)
      throw std::logic_error("raypipe timed model: a leaf with no triangle reached");
    t.lindex = t.nodeData.listIndex;
    t.lnum = t.nodeData.count;
    u.leafFifo.push(now_, t);
  } else {
    u.rs0.pipe.accept(now_, t);
  }
  busy(Unit::Trav, t);
  return false;
}

// The leaf FIFO's registered outputs to larb and to the list unit's leaf_max: its head is read
// when neither holds an item its receiver stalls.
void TimedPipe::travLeaves(TravUnit& u, bool toLarbStall, bool toListStall) {
  if (!u.travList.valid(now_) && !u.travLarb.valid(now_) && !u.leafFifo.any()) return;
  const bool listHeld = toListStall && u.travList.valid(now_);
  if (u.travList.valid(now_) && !listHeld)
    record(u.travList.value(now_).ray).leafMax = u.travList.value(now_).tMax;
  const bool larbHeld = toLarbStall && u.travLarb.valid(now_);
  const bool leafRe = u.leafFifo.shown(now_) && !larbHeld && !listHeld;
  if (leafRe) {
    const RayToken t = u.leafFifo.pop(now_);
    u.travLarb.set(now_, true, &t);
    u.travList.set(now_, true, &t);
    return;
  }
  if (!larbHeld && u.travLarb.valid(now_)) u.travLarb.set(now_, false, nullptr);
  if (!listHeld && u.travList.valid(now_)) u.travList.set(now_, false, nullptr);
}

// tcache: a 2-cycle read of the node into its FIFO (block RAM or timed_cache.h), from tarb's
// output `i`.
void TimedPipe::travCache(TravUnit& u, int i, bool tcToTravStall) {
  if (u.tcache.hitExiting(now_)) {
    RayToken t = u.tcache.takeHit(now_);
    const uint32_t address = sections_.nodes + t.node * kKdNodeWords;
    const uint32_t words[kKdNodeWords] = {memory_.read(address), memory_.read(address + 1)};
    t.nodeData = decodeKdNode(words);
    u.tcache.read.fifo.push(now_, t);
  }
  const bool tcUsStall = u.tcache.cycle(now_, tcToTravStall, cyclesSinceReset_);
  TimedQueue<RayToken>& in = c_.tarb.out(i);
  if (!in.shown(now_)) return;
  if (tcUsStall) {
    stall(Unit::Tcache);
    u.tcache.refused();
    return;
  }
  const RayToken t = in.pop(now_);
  u.tcache.accept(now_, t);
  busy(Unit::Tcache, t);
}

}  // namespace raypipe_timed
}  // namespace rtu
