// The timed model of seed 001's ray pipe: tarb, tcache, TRAV and raystore #0 (trav_unit.sv: the
// leaf FIFO and its two registered outputs, the math pipe beside its FIFO, the decision and its
// two registered outputs; trav_math.sv; simple_cache.sv). Timing rules: tarb as
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
  const std::array<const RayToken*, 4> offers = {
      c_.stackFifo.shown(now_) ? &c_.stackFifo.front() : nullptr,
      c_.notMissFifo.shown(now_) ? &c_.notMissFifo.front() : nullptr,
      c_.travTarb.valid(now_) ? &c_.travTarb.value(now_) : nullptr,
      c_.sintTarb.shown(now_) ? &c_.sintTarb.front() : nullptr};
  if (offers[0] || offers[1] || offers[2] || offers[3] || c_.tarb.holds())
    if (const RayToken* g = c_.tarb.arbitrate(now_, offers)) busy(Unit::Tarb, *g);
  const bool toTarbStall = c_.tarb.stallUs(2, now_);
  travDecision(toTarbStall);
  const bool pipeDsStall = (c_.travSs.valid(now_) && travToSsStall_) ||
                           (c_.travTarb.valid(now_) && toTarbStall);
  travMath(pipeDsStall);
}

void TimedPipe::travDecision(bool toTarbStall) {
  const bool ssHeld = c_.travSs.valid(now_) && travToSsStall_;
  const bool tarbHeld = c_.travTarb.valid(now_) && toTarbStall;
  if (!c_.travFifo.shown(now_)) {
    if (c_.travSs.valid(now_) && !ssHeld) c_.travSs.set(now_, false, nullptr);
    if (c_.travTarb.valid(now_) && !tarbHeld) c_.travTarb.set(now_, false, nullptr);
    return;
  }
  const uint32_t depth = static_cast<uint32_t>(config_.shortStackDepth);
  const Decision d = decide(c_.travFifo.front(), depth);
  bool re = true;
  if (d.toSs) re = re && !travToSsStall_;
  if (d.toTarb) re = re && !toTarbStall;
  if (!ssHeld) c_.travSs.set(now_, d.toSs && re, &d.ss);
  if (!tarbHeld) c_.travTarb.set(now_, d.toTarb && re, &d.tarb);
  if (!re) {
    stall(Unit::TravDecide);
    return;
  }
  RayRecord& r = record(d.ss.ray);
  if (d.ss.pushReq) {
    ++r.counts.pushes;
    if (d.ss.num == depth) ++r.counts.dropped;
  }
  c_.travFifo.pop(now_);
  busy(Unit::TravDecide, d.ss);
}

// raystore #0 -> the math pipe (14) beside its FIFO; then TRAV's input and leaf outputs.
void TimedPipe::travMath(bool pipeDsStall) {
  const bool rsToTravStall = c_.travPipe.usStall(now_, pipeDsStall, c_.travFifo.numLeft(now_));
  if (c_.travPipe.exiting(now_)) c_.travFifo.push(now_, c_.travPipe.take(now_));
  if (c_.rs0.fifo.shown(now_)) {
    if (rsToTravStall) {
      stall(Unit::TravMath);
    } else {
      RayToken t = c_.rs0.fifo.pop(now_);
      t.plane = planeTest(rays_[record(t.ray).index].ray, t.nodeData.axis,
                          bitsToFloat(t.nodeData.splitBits), t.tMin, t.tMax, config_.division);
      c_.travPipe.accept(now_, t);
      busy(Unit::TravMath, t);
    }
  }
  const bool rs0UsStall = c_.rs0.usStall(now_, rsToTravStall);
  if (c_.rs0.pipe.exiting(now_)) c_.rs0.fifo.push(now_, c_.rs0.pipe.take(now_));
  travInputAndLeaves(rs0UsStall, c_.larb.stallUs(0, now_));
}

void TimedPipe::travInputAndLeaves(bool rs0UsStall, bool toLarbStall) {
  bool tcToTravStall = false;
  if (c_.tcache.fifo.shown(now_)) {
    const RayToken& f = c_.tcache.fifo.front();
    const bool leaf = f.nodeData.leaf;
    tcToTravStall = leaf ? c_.leafFifo.full(now_) : rs0UsStall;
    if (tcToTravStall) {
      stall(Unit::Trav);
    } else {
      RayToken t = c_.tcache.fifo.pop(now_);
      RayRecord& r = record(t.ray);
      ++r.counts.nodes;
      if (leaf) {
        ++r.counts.leaves;
        if (t.nodeData.count == 0)
          throw std::logic_error("raypipe timed model: a leaf with no triangle reached");
        t.lindex = t.nodeData.listIndex;
        t.lnum = t.nodeData.count;
        c_.leafFifo.push(now_, t);
      } else {
        c_.rs0.pipe.accept(now_, t);
      }
      busy(Unit::Trav, t);
    }
  }
  // the leaf FIFO's registered outputs to larb and to the list unit's leaf_max
  if (c_.travList.valid(now_) || c_.travLarb.valid(now_) || c_.leafFifo.any()) {
    if (c_.travList.valid(now_))
      record(c_.travList.value(now_).ray).leafMax = c_.travList.value(now_).tMax;
    const bool larbHeld = toLarbStall && c_.travLarb.valid(now_);
    const bool leafRe = c_.leafFifo.shown(now_) && !larbHeld;
    if (leafRe) {
      const RayToken t = c_.leafFifo.pop(now_);
      c_.travLarb.set(now_, true, &t);
      c_.travList.set(now_, true, &t);
    } else {
      if (!larbHeld && c_.travLarb.valid(now_)) c_.travLarb.set(now_, false, nullptr);
      if (c_.travList.valid(now_)) c_.travList.set(now_, false, nullptr);
    }
  }
  // tcache: a 2-cycle read of the node into its FIFO
  const bool tcUsStall = c_.tcache.usStall(now_, tcToTravStall);
  if (c_.tcache.pipe.exiting(now_)) {
    RayToken t = c_.tcache.pipe.take(now_);
    const uint32_t address = sections_.nodes + t.node * kKdNodeWords;
    const uint32_t words[kKdNodeWords] = {memory_.read(address), memory_.read(address + 1)};
    t.nodeData = decodeKdNode(words);
    c_.tcache.fifo.push(now_, t);
  }
  if (!c_.tarb.out().shown(now_)) return;
  if (tcUsStall) {
    stall(Unit::Tcache);
    return;
  }
  const RayToken t = c_.tarb.out().pop(now_);
  c_.tcache.pipe.accept(now_, t);
  busy(Unit::Tcache, t);
}

}  // namespace raypipe_timed
}  // namespace rtu
