// The per-cycle reference of seed 001's ray pipe: the shortstack (R1
// RAYTRACER/shortstack/shortstack.sv): request and write FIFOs, the stack path (read, VS pipe 2,
// FIFO 3) and the restart path (read, compare, VS pipe 3, miss and restart FIFOs 4), the restart
// RAM's write arbitration.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "reference/raypipe_top.h"

namespace rtu {
namespace raypipe_ref {

// R1 RAYTRACER/shortstack/shortstack.sv: the stack path, the restart path, their request and
// write FIFOs (ports 0 and 1 for the traversal units, 2 for the list unit or SINT) and arbitration.
void Pipe::shortStack() {
  const uint32_t depth = static_cast<uint32_t>(config_.shortStackDepth);
  // inputs: each TRAV's request register (port i), the list unit's miss register, SINT's restart
  // write
  for (size_t i = 0; i < u_.trav.size(); ++i) {
    TravUnit& u = u_.trav[i];
    if (!u.ssValid || travToSsStall_[i]) continue;
    const Flit& f = u.ss;
    if (f.popReq) {
      Flit r = f;
      r.tMin = f.tMax;  // the new t_min is TRAV's t_max
      if (f.num == 0) {
        u_.restRead[i].push(now_, r);
      } else {
        r.wptr = (f.wptr + depth - 1) % depth;
        r.num = f.num - 1;
        u_.stackRead[i].push(now_, r);
      }
    }
    if (f.pushReq) {
      u.stackWrite.push(now_, f);
      ++slot(f.ray).pendingStackWrites;
    }
    if (f.restReq || f.maxsceneReq) {
      u_.restWrite[i].push(now_, f);
      ++slot(f.ray).pendingRestWrites;
    }
  }
  if (u_.toSsValid && !listToSsStall_) {
    Flit r = u_.toSs;
    r.tMin = u_.toSs.t;  // t_max_leaf
    if (r.num == 0) {
      u_.restRead[2].push(now_, r);
    } else {
      r.wptr = (r.wptr + depth - 1) % depth;
      r.num -= 1;
      u_.stackRead[2].push(now_, r);
    }
  }
  if (!u_.sintSs.empty() && !sintToSsStall_) {
    Flit w = u_.sintSs.front();
    w.restReq = w.maxsceneReq = true;  // SINT writes {node 0, t_max_scene}
    w.node = 0;
    u_.restWrite[2].push(now_, w);
    ++slot(w.ray).pendingRestWrites;
    u_.sintSs.pop();
  }
  // stack path: round-robin read of the three request FIFOs, 2-cycle read, FIFO 3 -> tarb[0]
  if (u_.tarb.accepted(0)) u_.stackFifo.pop();
  const bool stackUsStall = u_.stackPipe.usStall(u_.tarb.stallUs(0), u_.stackFifo.numLeft());
  if (u_.stackPipe.outValid(now_)) u_.stackFifo.push(now_, u_.stackPipe.out(now_));
  const int stackChoice =
      u_.stackReadChoice.choose([&](int i) { return !u_.stackRead[i].empty() && !stackUsStall; });
  bool stackReading = false;
  uint32_t readRow = 0;
  if (stackChoice >= 0) {
    Flit f = u_.stackRead[stackChoice].front();
    u_.stackRead[stackChoice].pop();
    const Slot& s = slot(f.ray);
    if (s.pendingStackWrites > 0)
      throw std::logic_error("raypipe reference: a pop read a stack row with a write pending");
    const StackEntry& e = s.stack[f.wptr];
    f.node = e.node;
    f.tMax = e.tMax;
    f.search = false;
    stackReading = true;
    readRow = f.wptr;
    u_.stackPipe.accept(f);
    busy(Unit::StackRead, f);
  } else {
    for (int i = 0; i < 3; ++i)
      if (!u_.stackRead[i].empty()) activity_.stall(Unit::StackRead);
  }
  stackWrites(stackReading, readRow);
  // restart path: round-robin read, compare with t_max_scene, 3-cycle pipe, miss or restart
  if (u_.shaderArb.accepted(3)) u_.missFifo.pop();
  if (u_.tarb.accepted(1)) u_.notMissFifo.pop();
  const bool restDsStall = u_.tarb.stallUs(1) || u_.shaderArb.stallUs(3);
  const int restLeft = std::min(u_.missFifo.numLeft(), u_.notMissFifo.numLeft());
  const bool restUsStall = u_.restPipe.usStall(restDsStall, restLeft);
  if (u_.restPipe.outValid(now_)) {
    const Flit& f = u_.restPipe.out(now_);
    if (f.miss) {
      u_.missFifo.push(now_, f);
    } else {
      ++slot(f.ray).counts.restarts;
      u_.notMissFifo.push(now_, f);
    }
  }
  const int restChoice =
      u_.restReadChoice.choose([&](int i) { return !u_.restRead[i].empty() && !restUsStall; });
  const bool restReading = restChoice >= 0;
  if (restReading) {
    Flit f = u_.restRead[restChoice].front();
    u_.restRead[restChoice].pop();
    const Slot& s = slot(f.ray);
    if (s.pendingRestWrites > 0 || !s.restWritten)
      throw std::logic_error("raypipe reference: a restart read with its record not written");
    f.miss = greaterEqual32(f.tMin, s.tMaxScene);  // altfp_compare aeb | agb
    f.node = s.restNode;
    f.tMax = s.tMaxScene;
    f.wptr = f.num = 0;
    f.search = false;
    f.isHit = false;
    u_.restPipe.accept(f);
    busy(Unit::RestartRead, f);
  } else {
    for (int i = 0; i < 3; ++i)
      if (!u_.restRead[i].empty()) activity_.stall(Unit::RestartRead);
  }
  // restart writes: three FIFOs onto the byte-enabled RAM's ports, the RTL's choice rule
  bool valid[3];
  for (int i = 0; i < 3; ++i) valid[i] = !u_.restWrite[i].empty();
  const int r0 = u_.restWritePointer, r1 = (r0 + 1) % 3, r2 = (r0 + 2) % 3;
  bool choice[3] = {false, false, false};
  choice[r0] = valid[r0];
  choice[r1] = valid[r1] && !(valid[r0] && restReading);
  choice[r2] = valid[r2] && (int(valid[r0]) + int(valid[r1]) + int(restReading) <= 1);
  if (choice[0] || choice[1] || choice[2]) u_.restWritePointer = (r0 + 1) % 3;
  for (int i = 0; i < 3; ++i) {
    if (!choice[i]) continue;
    const Flit& w = u_.restWrite[i].front();
    Slot& s = slot(w.ray);
    if (w.restReq) s.restNode = w.node;  // nodeID bytes when update_restnode (SINT: node 0)
    s.tMaxScene = w.tMax;                // t_max_scene bytes: restnode or maxscene update
    s.restWritten = true;
    --s.pendingRestWrites;
    u_.restWrite[i].pop();
  }
}

// The stack RAMs' writes (shortstack.sv stack_wfifo_choice): the write FIFO the 1-bit pointer names
// writes whenever it holds a row; the other too, unless both hold a write to the row the stack read
// takes this cycle; the pointer turns every cycle either holds one. With one traversal unit its
// FIFO writes every cycle it holds a row.
void Pipe::stackWrites(bool reading, uint32_t readRow) {
  std::array<bool, 2> valid{};
  for (size_t i = 0; i < u_.trav.size(); ++i) valid[i] = !u_.trav[i].stackWrite.empty();
  if (!valid[0] && !valid[1]) return;
  const size_t p = static_cast<size_t>(u_.stackWritePointer), other = 1 - p;
  std::array<bool, 2> write{};
  write[p] = valid[p];
  const bool conflict = valid[0] && valid[1] && reading &&
                        u_.trav[0].stackWrite.front().wptr == readRow &&
                        u_.trav[1].stackWrite.front().wptr == readRow;
  write[other] = valid[other] && !conflict;
  u_.stackWritePointer = static_cast<int>(other);
  for (size_t i = 0; i < 2; ++i) {
    if (!write[i]) continue;
    RegFifo<Flit>& fifo = u_.trav[i].stackWrite;
    const Flit& w = fifo.front();
    Slot& s = slot(w.ray);
    s.stack[w.wptr] = StackEntry{w.pushNode, w.tMax};
    --s.pendingStackWrites;
    fifo.pop();
  }
}

}  // namespace raypipe_ref
}  // namespace rtu
