// The per-cycle reference of seed 001's ray pipe: the list unit (R1 RAYTRACER/list/list_unit.sv: VS
// pipe 4, last FIFO 5, the hit pipe 2 and FIFO 3, the registered miss output) with raystore #2 and
// the bypassed pcalc.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "reference/raypipe_top.h"

namespace rtu {
namespace raypipe_ref {

// R1 RAYTRACER/list/list_unit.sv, then raystore #2 and the bypassed pcalc into the shader.
void Pipe::listUnit() {
  // raystore #2 -> shader arbiter input 0
  const bool rs2DsStall = u_.shaderArb.stallUs(0);
  if (u_.shaderArb.accepted(0)) u_.rs2.fifo.pop();
  const bool rs2UsStall = u_.rs2.usStall(rs2DsStall);
  if (u_.rs2.pipe.outValid(now_)) u_.rs2.fifo.push(now_, u_.rs2.pipe.out(now_));
  listToRsStall_ = rs2UsStall;
  // the hit FIFO (int_fifo) -> raystore #2
  if (!u_.listHitFifo.empty() && !listToRsStall_) {
    u_.rs2.pipe.accept(u_.listHitFifo.front());
    u_.listHitFifo.pop();
  }
  const bool hitPipeUsStall = u_.listHitPipe.usStall(listToRsStall_, u_.listHitFifo.numLeft());
  if (u_.listHitPipe.outValid(now_)) u_.listHitFifo.push(now_, u_.listHitPipe.out(now_));
  // the last FIFO's head: a hit to the hit pipe, a miss to the shortstack register
  const bool lastValid = !u_.listLast.empty();
  const Flit* head = lastValid ? &u_.listLast.front() : nullptr;
  const bool hitStall = lastValid && head->isHit && hitPipeUsStall;
  const bool missStall = lastValid && !head->isHit && u_.toSsValid && listToSsStall_;
  const bool hitGo = lastValid && head->isHit && !hitPipeUsStall;
  const bool missGo = lastValid && !head->isHit && (!u_.toSsValid || !listToSsStall_);
  if (hitGo) u_.listHitPipe.accept(*head);
  if (!u_.toSsValid || !listToSsStall_) {
    u_.toSsValidNext = lastValid && !head->isHit;
    if (missGo) u_.toSsNext = *head;
  }
  if (hitGo || missGo) u_.listLast.pop();
  // the list pipe (VS pipe 4): the record's update and, after a leaf's last triangle, its decision
  const bool listDsStall = missStall || hitStall;
  const bool listUsStall = u_.listPipe.usStall(listDsStall, u_.listLast.numLeft());
  if (u_.listPipe.outValid(now_)) {
    Flit f = u_.listPipe.out(now_);
    Slot& s = slot(f.ray);
    const bool choose = f.found.hit && (!greater32(f.found.t, s.tCur) || !s.hitCur);
    if (choose) {
      s.tCur = f.found.t;
      s.uCur = f.found.u;
      s.vCur = f.found.v;
      s.triCur = f.tri;
    }
    s.hitCur = s.hitCur || f.found.hit;
    if (f.last) {
      f.isHit = s.hitCur && !greater32(s.tCur, s.leafMax);
      if (f.isHit) {
        f.t = s.tCur;
        f.u = s.uCur;
        f.v = s.vCur;
        f.tri = s.triCur;
        s.hitCur = false;  // the record cleared (t_cur written 0)
        s.tCur = 0;
      } else {
        f.t = s.leafMax;
      }
      u_.listLast.push(now_, f);
    }
  }
  intToListStall_ = listUsStall;
  if (u_.intList.valid(now_)) {
    if (listUsStall) {
      activity_.stall(Unit::List);
    } else {
      u_.listPipe.accept(u_.intList.front());
      if (u_.intList.front().last) {  // leaf_max is read in the next cycle
        leafAccepts_[1] = leafAccepts_[0];
        leafAccepts_[0] = now_;
      }
      u_.intList.pop();
      busy(Unit::List, u_.intList.front());
    }
  }
}

}  // namespace raypipe_ref
}  // namespace rtu
