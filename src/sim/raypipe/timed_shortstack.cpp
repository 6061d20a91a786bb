// The timed model of seed 001's ray pipe: the shortstack (shortstack.sv, ports for two traversal
// units). Timing rules: each TRAV's request, the list unit's miss and SINT's restart record each go
// into a 3-deep request or write FIFO and stall on its `full`; the stack path reads its three
// request FIFOs round robin (the pointer turns whenever any is valid and its pipe does not stall),
// a 2-cycle read into a 3-entry FIFO to tarb[0]; the restart path likewise, comparing t_min with
// t_max_scene, a 3-cycle pipe into the miss FIFO (to the shader) or the restart FIFO (to tarb[1]);
// the stack write FIFOs (one per TRAV) write as stackWrites says; the restart RAM takes its three
// write FIFOs by the RTL's choice, a restart read taking one port.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "sim/raypipe/timed_pipe.h"

namespace rtu {
namespace raypipe_timed {
namespace {

// The round-robin read over three request FIFOs: the first shown from the pointer on; the
// pointer turns whenever one is shown and the path takes (`canRead`). Every head is looked at (a
// head seen shown books its group again).
int roundRobin(std::array<Fifo, 3>& fifos, int& pointer, int64_t now, bool canRead) {
  const bool shown[3] = {fifos[0].shown(now), fifos[1].shown(now), fifos[2].shown(now)};
  if (!canRead) return -1;
  for (int k = 0; k < 3; ++k) {
    const int i = (pointer + k) % 3;
    if (shown[i]) {
      pointer = (pointer + 1) % 3;
      return i;
    }
  }
  return -1;
}

int countWaiting(std::array<Fifo, 3>& fifos, int64_t now) {
  int waiting = 0;
  for (auto& f : fifos)
    if (f.shown(now)) ++waiting;
  return waiting;
}

}  // namespace

// Traversal unit i's request: into the request and write FIFOs of its port i.
bool TimedPipe::travToSsStall(size_t i) {
  Register& r = c_.trav[i].travSs;
  if (!r.valid(now_)) return false;
  const RayToken& f = r.value(now_);
  if (f.popReq) return f.num == 0 ? c_.restRead[i].full(now_) : c_.stackRead[i].full(now_);
  if (f.pushReq && f.restReq) return c_.stackWrite[i].full(now_) || c_.restWrite[i].full(now_);
  if (f.pushReq) return c_.stackWrite[i].full(now_);
  return c_.restWrite[i].full(now_);  // max-scene
}

bool TimedPipe::listToSsStall() {
  if (!c_.toSs.valid(now_)) return false;
  const RayToken& f = c_.toSs.value(now_);
  return f.num == 0 ? c_.restRead[2].full(now_) : c_.stackRead[2].full(now_);
}

void TimedPipe::shortStack() {
  shortStackInputs();
  stackPath();
  restartPath();
}

void TimedPipe::shortStackInputs() {
  const uint32_t depth = static_cast<uint32_t>(config_.shortStackDepth);
  auto popRequest = [&](RayToken r, float tMin, int port) {
    r.tMin = tMin;
    if (r.num == 0) {
      c_.restRead[static_cast<size_t>(port)].push(now_, r);
      return;
    }
    r.wptr = (r.wptr + depth - 1) % depth;
    r.num -= 1;
    c_.stackRead[static_cast<size_t>(port)].push(now_, r);
  };
  for (size_t i = 0; i < c_.trav.size(); ++i) {
    Register& r = c_.trav[i].travSs;
    if (!r.valid(now_) || travToSsStall_[i]) continue;
    const RayToken& f = r.value(now_);
    if (f.popReq) popRequest(f, f.tMax, static_cast<int>(i));  // the new t_min is TRAV's t_max
    if (f.pushReq) c_.stackWrite[i].push(now_, f);
    if (f.restReq || f.maxsceneReq) c_.restWrite[i].push(now_, f);
  }
  if (c_.toSs.valid(now_) && !listToSsStall_)
    popRequest(c_.toSs.value(now_), c_.toSs.value(now_).t, 2);  // t_max_leaf
  if (c_.sintSs.shown(now_) && !sintToSsStall_) {
    RayToken w = c_.sintSs.pop(now_);
    w.restReq = w.maxsceneReq = true;  // SINT writes {node 0, t_max_scene}
    w.node = 0;
    c_.restWrite[2].push(now_, w);
  }
}

void TimedPipe::stackPath() {
  if (c_.tarb.accepted(0, now_)) c_.stackFifo.pop(now_);
  bool reading = false;
  uint32_t readRow = 0;
  const bool anyRead = c_.stackRead[0].any() || c_.stackRead[1].any() || c_.stackRead[2].any();
  if (anyRead || c_.stackPipe.any()) {
    const bool usStall =
        c_.stackPipe.usStall(now_, c_.tarb.stallUs(0, now_), c_.stackFifo.numLeft(now_));
    if (c_.stackPipe.exiting(now_)) c_.stackFifo.push(now_, c_.stackPipe.take(now_));
    const int choice = roundRobin(c_.stackRead, c_.stackReadPointer, now_, !usStall);
    reading = choice >= 0;
    if (reading) {
      RayToken t = c_.stackRead[static_cast<size_t>(choice)].pop(now_);
      const StackRow& row = stackRow(t.ray, t.wptr);
      t.node = row.node;
      t.tMax = row.tMax;
      t.search = false;
      readRow = t.wptr;
      c_.stackPipe.accept(now_, t);
      busy(Unit::StackRead, t);
    } else {
      stalledInputs(Unit::StackRead, countWaiting(c_.stackRead, now_));
    }
  }
  stackWrites(reading, readRow);
}

// The stack RAMs' writes (shortstack.sv): the write FIFO the pointer names writes whenever it holds
// a row; the other too, unless both write the row the read takes this cycle; the pointer turns
// whenever either holds one. With one traversal unit its FIFO writes every cycle it holds a row.
void TimedPipe::stackWrites(bool reading, uint32_t readRow) {
  std::array<bool, 2> valid{};
  for (size_t i = 0; i < c_.stackWrite.size(); ++i) valid[i] = c_.stackWrite[i].shown(now_);
  if (!valid[0] && !valid[1]) return;
  const size_t p = static_cast<size_t>(c_.stackWritePointer), other = 1 - p;
  std::array<bool, 2> choice{};
  choice[p] = valid[p];
  const bool conflict = valid[0] && valid[1] && reading &&
                        c_.stackWrite[0].front().wptr == c_.stackWrite[1].front().wptr &&
                        readRow == c_.stackWrite[0].front().wptr;
  choice[other] = valid[other] && !conflict;
  c_.stackWritePointer = static_cast<int>(other);
  for (size_t i = 0; i < 2; ++i) {
    if (!choice[i]) continue;
    const RayToken w = c_.stackWrite[i].pop(now_);
    stackRow(w.ray, w.wptr) = StackRow{w.pushNode, w.tMax};
  }
}

void TimedPipe::restartPath() {
  if (c_.shaderArb.accepted(3, now_)) c_.missFifo.pop(now_);
  if (c_.tarb.accepted(1, now_)) c_.notMissFifo.pop(now_);
  bool reading = false;
  const bool anyRead = c_.restRead[0].any() || c_.restRead[1].any() || c_.restRead[2].any();
  if (anyRead || c_.restPipe.any()) {
    const bool dsStall = c_.tarb.stallUs(1, now_) || c_.shaderArb.stallUs(3, now_);
    const int left = std::min(c_.missFifo.numLeft(now_), c_.notMissFifo.numLeft(now_));
    const bool usStall = c_.restPipe.usStall(now_, dsStall, left);
    if (c_.restPipe.exiting(now_)) {
      const RayToken t = c_.restPipe.take(now_);
      if (t.miss) {
        c_.missFifo.push(now_, t);
      } else {
        ++record(t.ray).counts.restarts;
        c_.notMissFifo.push(now_, t);
      }
    }
    const int choice = roundRobin(c_.restRead, c_.restReadPointer, now_, !usStall);
    reading = choice >= 0;
    if (reading) {
      RayToken t = c_.restRead[static_cast<size_t>(choice)].pop(now_);
      const RayRecord& r = record(t.ray);
      t.miss = greaterEqual32(t.tMin, r.tMaxScene);  // altfp_compare aeb | agb
      t.node = r.restNode;
      t.tMax = r.tMaxScene;
      t.wptr = t.num = 0;
      t.search = t.isHit = false;
      c_.restPipe.accept(now_, t);
      busy(Unit::RestartRead, t);
    } else {
      stalledInputs(Unit::RestartRead, countWaiting(c_.restRead, now_));
    }
  }
  restartWrites(reading);
}

// The restart RAM's two ports over three write FIFOs: the first from the pointer always, the second
// unless the first wrote and a read takes a port, the third only when one port is left.
void TimedPipe::restartWrites(bool restReading) {
  bool valid[3];
  for (size_t i = 0; i < 3; ++i) valid[i] = c_.restWrite[i].shown(now_);
  if (!valid[0] && !valid[1] && !valid[2]) return;
  const int r0 = c_.restWritePointer, r1 = (r0 + 1) % 3, r2 = (r0 + 2) % 3;
  bool choice[3] = {false, false, false};
  choice[r0] = valid[r0];
  choice[r1] = valid[r1] && !(valid[r0] && restReading);
  choice[r2] = valid[r2] && (int(valid[r0]) + int(valid[r1]) + int(restReading) <= 1);
  c_.restWritePointer = (r0 + 1) % 3;
  for (size_t i = 0; i < 3; ++i) {
    if (!choice[i]) continue;
    const RayToken w = c_.restWrite[i].pop(now_);
    RayRecord& r = record(w.ray);
    if (w.restReq) r.restNode = w.node;  // the node when update_restnode (SINT: node 0)
    r.tMaxScene = w.tMax;
  }
}

}  // namespace raypipe_timed
}  // namespace rtu
