// The per-cycle reference of seed 001's ray pipe: tarb, tcache, TRAV and raystore #0 (R1
// RAYTRACER/trav/trav_unit.sv: the leaf FIFO 8 and its two output registers, the 14-cycle math pipe
// beside its 15-deep FIFO, the decision and its two output registers).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "reference/raypipe_top.h"

namespace rtu {
namespace raypipe_ref {

// tarb -> tcache -> TRAV (R1 RAYTRACER/trav/trav_unit.sv, trav_math.sv) with raystore #0.
void Pipe::traversal() {
  u_.tarb.arbitrate(now_);
  if (const Flit* g = u_.tarb.granted()) busy(Unit::Tarb, *g);
  const int depth = config_.shortStackDepth;
  const bool toTarbStall = u_.tarb.stallUs(2);
  const bool toLarbStall = u_.larb.stallUs(0);
  // TRAV's decision over the head of its 15-deep FIFO
  bool goodToSs = false, goodToTarb = false;
  Flit ssReq, tarbReq;
  if (!u_.travFifo.empty()) {
    const Flit& f = u_.travFifo.front();
    const KdPlaneTest& p = f.plane;
    const bool lowEmpty = f.nodeData.lowEmpty, highEmpty = f.nodeData.highEmpty;
    const uint32_t low = f.node + 1, high = f.nodeData.high;
    const bool pop = (p.onlyLow && lowEmpty) || (p.onlyHigh && highEmpty);
    const bool push = !lowEmpty && !highEmpty && (p.lowThenHigh || p.highThenLow);
    const bool restReq = f.search && push;
    const bool maxscene = f.search && ((p.lowThenHigh && highEmpty) || (p.highThenLow && lowEmpty));
    goodToSs = pop || push || restReq || maxscene;
    goodToTarb = !pop;
    ssReq = f;
    ssReq.popReq = pop;
    ssReq.pushReq = push;
    ssReq.restReq = restReq;
    ssReq.maxsceneReq = maxscene;
    ssReq.pushNode = p.lowThenHigh ? high : low;
    tarbReq = f;
    const bool toLow = p.onlyLow || (p.lowThenHigh && !lowEmpty) || (p.highThenLow && highEmpty);
    tarbReq.node = toLow ? low : high;
    if (p.onlyLow || p.onlyHigh) {
      tarbReq.tMin = f.tMin;
      tarbReq.tMax = f.tMax;
    } else if ((p.lowThenHigh && !lowEmpty) || (p.highThenLow && !highEmpty)) {
      tarbReq.tMin = f.tMin;
      tarbReq.tMax = p.tMid;
    } else {
      tarbReq.tMin = p.tMid;
      tarbReq.tMax = f.tMax;
    }
    tarbReq.wptr = push ? (f.wptr + 1) % static_cast<uint32_t>(depth) : f.wptr;
    tarbReq.num = push ? std::min<uint32_t>(f.num + 1, static_cast<uint32_t>(depth)) : f.num;
    tarbReq.search = f.search && !push;
  }
  bool re = false;
  if (goodToSs && goodToTarb)
    re = !travToSsStall_ && !toTarbStall;
  else if (goodToSs)
    re = !travToSsStall_;
  else if (goodToTarb)
    re = !toTarbStall;
  u_.travSsValidNext = (u_.travSsValid && travToSsStall_) || (goodToSs && re);
  if (!(u_.travSsValid && travToSsStall_)) u_.travSsNext = ssReq;
  u_.travTarbValidNext = (u_.travTarbValid && toTarbStall) || (goodToTarb && re);
  if (!(u_.travTarbValid && toTarbStall)) u_.travTarbNext = tarbReq;
  if (re) {
    Slot& s = slot(ssReq.ray);
    if (ssReq.pushReq) {
      ++s.counts.pushes;
      if (ssReq.num == static_cast<uint32_t>(depth)) ++s.counts.dropped;
    }
    u_.travFifo.pop();
    busy(Unit::TravDecide, ssReq);
  } else if (!u_.travFifo.empty()) {
    activity_.stall(Unit::TravDecide);
  }
  // the math pipe (14) beside the FIFO, fed by raystore #0
  const bool pipeDsStall = (u_.travSsValid && travToSsStall_) || (u_.travTarbValid && toTarbStall);
  const bool rsToTravStall = u_.travPipe.usStall(pipeDsStall, u_.travFifo.numLeft());
  if (u_.travPipe.outValid(now_)) u_.travFifo.push(now_, u_.travPipe.out(now_));
  if (!u_.rs0.fifo.empty()) {
    if (rsToTravStall) {
      activity_.stall(Unit::TravMath);
    } else {
      Flit f = u_.rs0.fifo.front();
      u_.rs0.fifo.pop();
      f.plane = planeTest(slot(f.ray).ray, f.nodeData.axis, bitsToFloat(f.nodeData.splitBits),
                          f.tMin, f.tMax, config_.division);
      u_.travPipe.accept(f);
      busy(Unit::TravMath, f);
    }
  }
  const bool rs0UsStall = u_.rs0.usStall(rsToTravStall);
  if (u_.rs0.pipe.outValid(now_)) u_.rs0.fifo.push(now_, u_.rs0.pipe.out(now_));
  // TRAV's input from tcache: a leaf into the leaf FIFO, an interior node to raystore #0
  bool tcToTravStall = false;
  if (!u_.tcache.fifo.empty()) {
    const Flit& f = u_.tcache.fifo.front();
    const bool leaf = f.nodeData.leaf;
    tcToTravStall = (u_.leafFifo.full() && leaf) || (rs0UsStall && !leaf);
    if (tcToTravStall) {
      activity_.stall(Unit::Trav);
    } else {
      Slot& s = slot(f.ray);
      ++s.counts.nodes;
      if (leaf) {
        ++s.counts.leaves;
        if (f.nodeData.count == 0)
          throw std::logic_error("raypipe reference: a leaf with no triangle reached");
        Flit l = f;
        l.lindex = f.nodeData.listIndex;
        l.lnum = f.nodeData.count;
        u_.leafFifo.push(now_, l);
      } else {
        u_.rs0.pipe.accept(f);
      }
      u_.tcache.fifo.pop();
      busy(Unit::Trav, f);
    }
  }
  // the leaf FIFO's two registered outputs: to larb and to the list unit (leaf_max)
  if (u_.travListValid) slot(u_.travList.ray).leafMax = u_.travList.tMax;
  const bool leafRe = !u_.leafFifo.empty() && (!u_.travLarbValid || !toLarbStall);
  u_.travLarbValidNext = (toLarbStall && u_.travLarbValid) || leafRe;
  u_.travListValidNext = leafRe;
  if (leafRe) {
    u_.travLarbNext = u_.leafFifo.front();
    u_.travListNext = u_.leafFifo.front();
    u_.leafFifo.pop();
  }
  // tcache (2-cycle block RAM or the set-associative cache, 3-entry FIFO)
  const bool tcUsStall = u_.tcache.cycle(now_, tcToTravStall, u_.dram, cyclesSinceReset_);
  Flit hit;
  if (u_.tcache.exitHit(now_, hit)) {
    const uint32_t address = sections_.nodes + hit.node * kKdNodeWords;
    const uint32_t words[kKdNodeWords] = {memory_.read(address), memory_.read(address + 1)};
    hit.nodeData = decodeKdNode(words);
    u_.tcache.fifo.push(now_, hit);
  }
  auto& tarbOut = u_.tarb.out();
  if (tarbOut.valid(now_)) {
    if (tcUsStall) {
      activity_.stall(Unit::Tcache);
      u_.tcache.refused();
    } else {
      u_.tcache.accept(tarbOut.front());
      tarbOut.pop();
      busy(Unit::Tcache, tarbOut.front());
    }
  }
}

}  // namespace raypipe_ref
}  // namespace rtu
