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

// R1 RAYTRACER/shortstack/shortstack.sv with one traversal unit: the stack path, the restart
// path, their request and write FIFOs and arbitration.
void Pipe::shortStack() {
  const uint32_t depth = static_cast<uint32_t>(config_.shortStackDepth);
  // inputs: TRAV's request register, the list unit's miss register, SINT's restart write
  if (u_.travSsValid && !travToSsStall_) {
    const Flit& f = u_.travSs;
    if (f.popReq) {
      Flit r = f;
      r.tMin = f.tMax;  // the new t_min is TRAV's t_max
      if (f.num == 0) {
        u_.restRead[0].push(now_, r);
      } else {
        r.wptr = (f.wptr + depth - 1) % depth;
        r.num = f.num - 1;
        u_.stackRead[0].push(now_, r);
      }
    }
    if (f.pushReq) {
      u_.stackWrite.push(now_, f);
      ++slot(f.ray).pendingStackWrites;
    }
    if (f.restReq || f.maxsceneReq) {
      u_.restWrite[0].push(now_, f);
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
    u_.stackPipe.accept(f);
    busy(Unit::StackRead, f);
  } else {
    for (int i = 0; i < 3; ++i)
      if (!u_.stackRead[i].empty()) activity_.stall(Unit::StackRead);
  }
  // the stack write FIFO (one traversal unit: written whenever it holds a push)
  if (!u_.stackWrite.empty()) {
    const Flit& w = u_.stackWrite.front();
    Slot& s = slot(w.ray);
    s.stack[w.wptr] = StackEntry{w.pushNode, w.tMax};
    --s.pendingStackWrites;
    u_.stackWrite.pop();
  }
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

}  // namespace raypipe_ref
}  // namespace rtu
