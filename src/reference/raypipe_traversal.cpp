// The per-cycle reference of seed 001's ray pipe: tarb, tcache, TRAV and raystore #0 (R1
// RAYTRACER/trav/trav_unit.sv: the leaf FIFO 8 and its two output registers, the 14-cycle math pipe
// beside its 15-deep FIFO, the decision and its two output registers).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "reference/raypipe_top.h"

namespace rtu {
namespace raypipe_ref {

// tarb -> tcache -> TRAV (R1 RAYTRACER/trav/trav_unit.sv, trav_math.sv) with raystore #0, per
// traversal unit (raypipe_2trav.sv: tarb's output i feeds unit i).
void Pipe::traversal() {
  u_.tarb.arbitrate(now_);
  for (int o = 0; o < u_.tarb.outputs(); ++o)
    if (const Flit* g = u_.tarb.granted(o)) busy(Unit::Tarb, *g);
  const std::array<bool, 2> toListStall = leafMaxStalls();
  for (size_t i = 0; i < u_.trav.size(); ++i)
    travUnit(u_.trav[i], static_cast<int>(i), toListStall[i]);
}

// The list unit's leaf_max RAM (list_unit.sv): port A is its own read in the cycle after a leaf's
// last triangle entered it, else unit 0's write; port B the other write. When both units write and
// the list reads, the unit rrp names waits (rrp 0: unit 1) and rrp turns.
std::array<bool, 2> Pipe::leafMaxStalls() {
  if (u_.trav.size() < 2) return {false, false};
  const bool read = leafAccepts_[0] == now_ - 1 || leafAccepts_[1] == now_ - 1;
  if (!read || !u_.trav[0].listValid || !u_.trav[1].listValid) return {false, false};
  const bool rrp = leafMaxPointer_ != 0;
  leafMaxPointer_ ^= 1;
  return {rrp, !rrp};
}

void Pipe::travUnit(TravUnit& u, int i, bool toListStall) {
  const bool toTarbStall = u_.tarb.stallUs(2 + i);
  const bool toLarbStall = u_.larb.stallUs(i);
  const bool toSsStall = travToSsStall_[static_cast<size_t>(i)];
  const int depth = config_.shortStackDepth;
  // TRAV's decision over the head of its 15-deep FIFO
  bool goodToSs = false, goodToTarb = false;
  Flit ssReq, tarbReq;
  if (!u.travFifo.empty()) {
    const Flit& f = u.travFifo.front();
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
    re = !toSsStall && !toTarbStall;
  else if (goodToSs)
    re = !toSsStall;
  else if (goodToTarb)
    re = !toTarbStall;
  u.ssValidNext = (u.ssValid && toSsStall) || (goodToSs && re);
  if (!(u.ssValid && toSsStall)) u.ssNext = ssReq;
  u.tarbValidNext = (u.tarbValid && toTarbStall) || (goodToTarb && re);
  if (!(u.tarbValid && toTarbStall)) u.tarbOutNext = tarbReq;
  if (re) {
    Slot& s = slot(ssReq.ray);
    if (ssReq.pushReq) {
      ++s.counts.pushes;
      if (ssReq.num == static_cast<uint32_t>(depth)) ++s.counts.dropped;
    }
    u.travFifo.pop();
    busy(Unit::TravDecide, ssReq);
  } else if (!u.travFifo.empty()) {
    activity_.stall(Unit::TravDecide);
  }
  // the math pipe (14) beside the FIFO, fed by raystore #0
  const bool pipeDsStall = (u.ssValid && toSsStall) || (u.tarbValid && toTarbStall);
  const bool rsToTravStall = u.travPipe.usStall(pipeDsStall, u.travFifo.numLeft());
  if (u.travPipe.outValid(now_)) u.travFifo.push(now_, u.travPipe.out(now_));
  if (!u.rs0.fifo.empty()) {
    if (rsToTravStall) {
      activity_.stall(Unit::TravMath);
    } else {
      Flit f = u.rs0.fifo.front();
      u.rs0.fifo.pop();
      f.plane = planeTest(slot(f.ray).ray, f.nodeData.axis, bitsToFloat(f.nodeData.splitBits),
                          f.tMin, f.tMax, config_.division);
      u.travPipe.accept(f);
      busy(Unit::TravMath, f);
    }
  }
  const bool rs0UsStall = u.rs0.usStall(rsToTravStall);
  if (u.rs0.pipe.outValid(now_)) u.rs0.fifo.push(now_, u.rs0.pipe.out(now_));
  // TRAV's input from tcache: a leaf into the leaf FIFO, an interior node to raystore #0
  bool tcToTravStall = false;
  if (!u.tcache.fifo.empty()) {
    const Flit& f = u.tcache.fifo.front();
    const bool leaf = f.nodeData.leaf;
    tcToTravStall = (u.leafFifo.full() && leaf) || (rs0UsStall && !leaf);
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
        u.leafFifo.push(now_, l);
      } else {
        u.rs0.pipe.accept(f);
      }
      u.tcache.fifo.pop();
      busy(Unit::Trav, f);
    }
  }
  // the leaf FIFO's two registered outputs: to larb and to the list unit (leaf_max)
  // (with two units a leaf_max write can wait: leafMaxStalls; the leaf FIFO is not read meanwhile)
  const bool listHeld = toListStall && u.listValid;
  if (u.listValid && !listHeld) slot(u.list.ray).leafMax = u.list.tMax;
  const bool larbHeld = toLarbStall && u.larbValid;
  const bool leafRe = !u.leafFifo.empty() && !larbHeld && !listHeld;
  u.larbValidNext = larbHeld || leafRe;
  u.listValidNext = listHeld || leafRe;
  if (leafRe) {
    u.larbOutNext = u.leafFifo.front();
    u.listNext = u.leafFifo.front();
    u.leafFifo.pop();
  }
  // tcache (2-cycle block RAM or the set-associative cache, 3-entry FIFO)
  const bool tcUsStall = u.tcache.cycle(now_, tcToTravStall, u_.dram, cyclesSinceReset_);
  Flit hit;
  if (u.tcache.exitHit(now_, hit)) {
    const uint32_t address = sections_.nodes + hit.node * kKdNodeWords;
    const uint32_t words[kKdNodeWords] = {memory_.read(address), memory_.read(address + 1)};
    hit.nodeData = decodeKdNode(words);
    u.tcache.fifo.push(now_, hit);
  }
  auto& tarbOut = u_.tarb.out(i);
  if (tarbOut.valid(now_)) {
    if (tcUsStall) {
      activity_.stall(Unit::Tcache);
      u.tcache.refused();
    } else {
      u.tcache.accept(tarbOut.front());
      tarbOut.pop();
      busy(Unit::Tcache, tarbOut.front());
    }
  }
}

}  // namespace raypipe_ref
}  // namespace rtu
