// The timed model of seed 001's ray pipe: the list unit (list_unit.sv) with raystore #2 and the
// bypassed pcalc. Timing rules: a 4-cycle pipe updates the ray's record at its end and, after a
// leaf's last triangle, decides into the 5-deep last FIFO; its head goes on as a hit through a
// 2-cycle pipe, a 3-entry FIFO and raystore #2 (2 + 3) into the shader's arbiter [0], or as a miss
// into a registered output to the shortstack.
#include "sim/raypipe/timed_pipe.h"

namespace rtu {
namespace raypipe_timed {

void TimedPipe::listUnit() {
  // raystore #2 -> the shader's arbiter [0]
  if (c_.shaderArb.accepted(0, now_)) c_.rs2.fifo.pop(now_);
  listToRsStall_ = c_.rs2.usStall(now_, c_.shaderArb.stallUs(0, now_));
  if (c_.rs2.pipe.exiting(now_)) c_.rs2.fifo.push(now_, c_.rs2.pipe.take(now_));
  if (c_.listHitFifo.shown(now_) && !listToRsStall_)
    c_.rs2.pipe.accept(now_, c_.listHitFifo.pop(now_));
  const bool hitPipeUsStall =
      c_.listHitPipe.usStall(now_, listToRsStall_, c_.listHitFifo.numLeft(now_));
  if (c_.listHitPipe.exiting(now_)) c_.listHitFifo.push(now_, c_.listHitPipe.take(now_));
  // the last FIFO's head: a hit into the hit pipe, a miss into the shortstack register
  const bool missHeld = c_.toSs.valid(now_) && listToSsStall_;
  bool hitStall = false, missStall = false;
  if (c_.listLast.shown(now_)) {
    const bool isHit = c_.listLast.front().isHit;
    hitStall = isHit && hitPipeUsStall;
    missStall = !isHit && missHeld;
    if (!hitStall && !missStall) {
      const RayToken t = c_.listLast.pop(now_);
      if (isHit) c_.listHitPipe.accept(now_, t);
      if (!missHeld) c_.toSs.set(now_, !isHit, &t);
    } else if (!missHeld) {
      c_.toSs.set(now_, false, nullptr);
    }
  } else if (c_.toSs.valid(now_) && !missHeld) {
    c_.toSs.set(now_, false, nullptr);
  }
  listRecord(missStall || hitStall);
}

// The list pipe (4): the ray's record updated at its end; after a leaf's last triangle, the hit
// when the record's t is within the leaf's t_max, else a miss carrying t_max_leaf.
void TimedPipe::listRecord(bool dsStall) {
  const bool usStall = c_.listPipe.usStall(now_, dsStall, c_.listLast.numLeft(now_));
  if (c_.listPipe.exiting(now_)) {
    RayToken t = c_.listPipe.take(now_);
    RayRecord& r = record(t.ray);
    if (t.found.hit && (!greater32(t.found.t, r.tCur) || !r.hitCur)) {
      r.tCur = t.found.t;
      r.uCur = t.found.u;
      r.vCur = t.found.v;
      r.triCur = t.tri;
    }
    r.hitCur = r.hitCur || t.found.hit;
    if (t.last) {
      t.isHit = r.hitCur && !greater32(r.tCur, r.leafMax);
      t.t = t.isHit ? r.tCur : r.leafMax;
      if (t.isHit) {
        t.u = r.uCur;
        t.v = r.vCur;
        t.tri = r.triCur;
        r.hitCur = false;  // the record cleared (t_cur written 0)
        r.tCur = 0;
      }
      c_.listLast.push(now_, t);
    }
  }
  intToListStall_ = usStall;
  if (!c_.intList.shown(now_)) return;
  if (usStall) {
    stall(Unit::List);
    return;
  }
  const RayToken t = c_.intList.pop(now_);
  if (t.last && c_.leafReads[0] != now_) {  // leaf_max is read in the next cycle
    c_.leafReads[1] = c_.leafReads[0];
    c_.leafReads[0] = now_;
  }
  c_.listPipe.accept(now_, t);
  busy(Unit::List, t);
}

}  // namespace raypipe_timed
}  // namespace rtu
