// The per-cycle reference of seed 001's ray pipe (raypipe_cycles.h): the top, stepping every
// unit once a cycle. Within a cycle the combinational stalls are evaluated from the pixel buffer
// back to the PRG, each after the stalls it depends on, as the RTL's always_comb blocks settle;
// every register, FIFO and pipe then takes its new state at the cycle's end (tick). The units'
// state and rules are in raypipe_units.h.
#include "reference/raypipe_cycles.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "reference/raypipe_units.h"

namespace rtu {
namespace raypipe_ref {
namespace {

class Pipe {
 public:
  Pipe(const RaypipeConfig& config, const KdImage& image, const std::vector<RaypipeCycleRay>& rays)
      : config_(config),
        memory_(image.memory()),
        sections_(sectionsOf(decodeKdHeader(image.words.data()))),
        rays_(rays),
        u_(config) {
    results_.resize(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) results_[i].pixelId = rays[i].pixelId;
    slots_.resize(static_cast<size_t>(config.raysInFlight));
    for (auto& slot : slots_) slot.stack.resize(static_cast<size_t>(config.shortStackDepth));
    for (int id = 0; id < config.raysInFlight; ++id) u_.idFifo.preload(static_cast<uint32_t>(id));
  }

  RaypipeCycleRun run() {
    const auto start = std::chrono::steady_clock::now();
    int64_t lastProgress = 0;
    size_t exited = 0, written = 0;
    while (written < rays_.size()) {
      const int64_t before = activity_.total();
      step(exited, written);
      if (activity_.total() != before) lastProgress = now_;
      if (now_ - lastProgress > 1000000)
        throw std::logic_error("raypipe reference: no progress for a million cycles at cycle " +
                               std::to_string(now_));
      ++now_;
    }
    RaypipeCycleRun run;
    run.results = results_;
    for (const auto& r : results_) run.lastExitCycle = std::max(run.lastExitCycle, r.exitCycle);
    run.frameCycles = run.lastExitCycle + 1;
    run.lastWriteCycle = lastWrite_;
    run.units = activity_.table();
    run.fifos = u_.fifoPeaks();
    run.maxRaysInFlight = maxInFlight_;
    run.staleListHits = staleListHits_;
    run.hostSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return run;
  }

 private:
  Slot& slot(uint32_t ray) { return slots_[ray]; }

  void step(size_t& exited, size_t& written);
  void shaderReturn(size_t& exited, size_t& written);
  void listUnit();
  void intersection();
  void traversal();
  void shortStack();
  void sceneIntersection();
  void shaderIssueAndPrg();
  void tick();

  const RaypipeConfig& config_;
  WordMemory memory_;
  KdSections sections_;
  const std::vector<RaypipeCycleRay>& rays_;
  Units u_;
  std::vector<Slot> slots_;
  std::vector<RaypipeCycleResult> results_;
  Activity activity_;
  int64_t now_ = 0;
  int64_t lastWrite_ = -1;
  size_t issued_ = 0;  // pixels the PRG accepted
  int inFlight_ = 0, maxInFlight_ = 0;
  int64_t staleListHits_ = 0;
  // Stalls every unit reads, computed at the cycle's start from registered state.
  bool travToSsStall_ = false, listToSsStall_ = false, sintToSsStall_ = false;
  bool listToRsStall_ = false, intToListStall_ = false, sintUsStall_ = false;
};

void Pipe::step(size_t& exited, size_t& written) {
  // The arbiters' offers: every input's valid is a register or a FIFO's flag.
  u_.offerAll(now_);
  travToSsStall_ = u_.travToSsStall();
  listToSsStall_ = u_.listToSsStall();
  sintToSsStall_ = !u_.sintSs.empty() && u_.restWrite[2].full();
  shaderReturn(exited, written);
  listUnit();
  intersection();
  traversal();
  shortStack();
  sceneIntersection();
  shaderIssueAndPrg();
  tick();
}

// R1 RAYTRACER/shader/simple_shade_unit.sv (return side) and DEMOS/t5.sv's pixel buffer.
void Pipe::shaderReturn(size_t& exited, size_t& written) {
  u_.shaderArb.arbitrate(now_);
  const bool pbFull = u_.pixelBuffer.full();
  const bool dataRe = !pbFull && !u_.shaderData.empty();
  const bool pipeDsStall = pbFull && !u_.shaderData.empty();
  const bool pipeUsStall = u_.shaderPipe.usStall(pipeDsStall, u_.shaderData.numLeft());
  auto& arbOut = u_.shaderArb.out();
  const bool arbValid = arbOut.valid(now_);
  if (arbValid && pipeUsStall) activity_.stall(Unit::ShaderReturn);
  if (arbValid && !pipeUsStall) {
    const Flit& f = arbOut.front();
    Slot& s = slot(f.ray);
    if (!s.busy)
      throw std::logic_error("raypipe reference: a result for the free ray id " +
                             std::to_string(f.ray) + " at cycle " + std::to_string(now_) +
                             (f.isHit     ? " (hit)"
                              : f.boxMiss ? " (box miss)"
                                          : " (miss)"));
    RaypipeCycleResult& r = results_[s.index];
    r.hit = f.isHit;
    r.boxMiss = f.boxMiss;
    if (f.isHit) {
      r.t = f.t;
      r.u = f.u;
      r.v = f.v;
      r.primitive = f.tri;
    }
    if (!f.isHit && !f.boxMiss && s.hitCur) ++staleListHits_;
    r.counts = s.counts;
    r.rayId = f.ray;
    s.busy = false;
    --inFlight_;
    Flit out = f;
    out.index = s.index;
    u_.shaderPipe.accept(out);
    u_.idFifo.push(now_, f.ray);  // rayID_wrreq: the id is free again
    arbOut.pop();
    activity_.busy(Unit::ShaderReturn);
  }
  if (u_.shaderPipe.outValid(now_)) u_.shaderData.push(now_, u_.shaderPipe.out(now_));
  if (dataRe) {
    const Flit& f = u_.shaderData.front();
    RaypipeCycleResult& r = results_[f.index];
    if (r.exitCycle >= 0) throw std::logic_error("raypipe reference: a pixel left twice");
    r.exitCycle = now_;
    ++exited;
    u_.pixelBuffer.push(now_, f);
    u_.shaderData.pop();
  }
  // The SRAM writer: one pixel a cycle while the buffer holds one (no VGA window).
  if (!u_.pixelBuffer.empty()) {
    u_.pixelBuffer.pop();
    lastWrite_ = now_;
    ++written;
    activity_.busy(Unit::PixelWriter);
  }
}

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
      u_.intList.pop();
      activity_.busy(Unit::List);
    }
  }
}

// larb -> lcache -> icache -> raystore #1 -> INT (R1 RAYTRACER/int/int_unit.sv, int_math.sv;
// RAYTRACER/caches/simple_cache.sv, raystore/raystore_simple.sv).
void Pipe::intersection() {
  u_.larb.arbitrate(now_);
  if (u_.larb.accepted(1)) u_.intLarb.pop();
  // 256 - max(usedw of the list and larb FIFOs), or the shadow FIFO's free slots if fewer
  const int minLeft = std::min({u_.intList.numLeft(), u_.intLarb.numLeft(), u_.intShaderNumLeft});
  const bool intDsStall = u_.larb.stallUs(1) || intToListStall_;
  const bool intUsStall = u_.intPipe.usStall(intDsStall, minLeft);
  if (u_.intPipe.outValid(now_)) {
    const Flit& f = u_.intPipe.out(now_);
    if (f.found.hit || f.last) u_.intList.push(now_, f);
    if (!f.last) {
      Flit next = f;
      next.found = KdTriangleHit{};
      u_.intLarb.push(now_, next);
    }
  }
  const bool rsToIntValid = !u_.rs1.fifo.empty();
  const bool rsToIntStall = intUsStall && rsToIntValid;
  if (rsToIntValid) {
    if (rsToIntStall) {
      activity_.stall(Unit::Int);
    } else {
      Flit f = u_.rs1.fifo.front();
      u_.rs1.fifo.pop();
      Slot& s = slot(f.ray);
      UttmWords words{};
      const uint32_t base = sections_.uttms + f.tri * kKdUttmWords;
      for (int i = 0; i < kUttmWords; ++i) words[i] = memory_.read(base + i);
      f.found = intersectUnitTriangle(s.ray, unpackUttm(words), config_.division);
      ++s.counts.triangleTests;
      f.lnum -= 1;  // lnum_left - 1, lindex + 1 at entry
      f.lindex += 1;
      f.last = f.lnum == 0;
      u_.intPipe.accept(f);
      activity_.busy(Unit::Int);
    }
  }
  const bool rs1UsStall = u_.rs1.usStall(rsToIntStall);
  if (u_.rs1.pipe.outValid(now_)) u_.rs1.fifo.push(now_, u_.rs1.pipe.out(now_));
  // icache: its fifo's re = ~ds_stall; raystore #1 takes it unless stalling
  if (!u_.icache.fifo.empty() && !rs1UsStall) {
    u_.rs1.pipe.accept(u_.icache.fifo.front());
    u_.icache.fifo.pop();
  }
  const bool icUsStall = u_.icache.usStall(rs1UsStall);
  if (u_.icache.pipe.outValid(now_)) u_.icache.fifo.push(now_, u_.icache.pipe.out(now_));
  if (!u_.lcache.fifo.empty() && !icUsStall) {
    u_.icache.pipe.accept(u_.lcache.fifo.front());
    u_.lcache.fifo.pop();
    activity_.busy(Unit::Icache);
  }
  const bool lcUsStall = u_.lcache.usStall(icUsStall);
  if (u_.lcache.pipe.outValid(now_)) {
    Flit f = u_.lcache.pipe.out(now_);
    f.tri = memory_.read(sections_.lists + f.lindex);
    u_.lcache.fifo.push(now_, f);
  }
  auto& larbOut = u_.larb.out();
  if (larbOut.valid(now_)) {
    if (lcUsStall) {
      activity_.stall(Unit::Lcache);
    } else {
      u_.lcache.pipe.accept(larbOut.front());
      larbOut.pop();
      activity_.busy(Unit::Lcache);
    }
  }
}

// tarb -> tcache -> TRAV (R1 RAYTRACER/trav/trav_unit.sv, trav_math.sv) with raystore #0.
void Pipe::traversal() {
  u_.tarb.arbitrate(now_);
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
    activity_.busy(Unit::TravDecide);
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
      activity_.busy(Unit::TravMath);
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
      activity_.busy(Unit::Trav);
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
  // tcache (2-cycle block RAM, 3-entry FIFO)
  const bool tcUsStall = u_.tcache.usStall(tcToTravStall);
  if (u_.tcache.pipe.outValid(now_)) {
    Flit f = u_.tcache.pipe.out(now_);
    const uint32_t address = sections_.nodes + f.node * kKdNodeWords;
    const uint32_t words[kKdNodeWords] = {memory_.read(address), memory_.read(address + 1)};
    f.nodeData = decodeKdNode(words);
    u_.tcache.fifo.push(now_, f);
  }
  auto& tarbOut = u_.tarb.out();
  if (tarbOut.valid(now_)) {
    if (tcUsStall) {
      activity_.stall(Unit::Tcache);
    } else {
      u_.tcache.pipe.accept(tarbOut.front());
      tarbOut.pop();
      activity_.busy(Unit::Tcache);
    }
  }
}

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
    activity_.busy(Unit::StackRead);
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
    activity_.busy(Unit::RestartRead);
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

// R1 RAYTRACER/scene_int/scene_int.sv: the 18-cycle pipe and its three 18-deep FIFOs.
void Pipe::sceneIntersection() {
  if (u_.tarb.accepted(3)) u_.sintTarb.pop();
  if (u_.shaderArb.accepted(2)) u_.sintShader.pop();
  const bool dsStall = u_.tarb.stallUs(3) || sintToSsStall_ || u_.shaderArb.stallUs(2);
  const int left = std::min({u_.sintTarb.numLeft(), u_.sintSs.numLeft(), u_.sintShader.numLeft()});
  sintUsStall_ = u_.sintPipe.usStall(dsStall, left);
  if (u_.sintPipe.outValid(now_)) {
    Flit f = u_.sintPipe.out(now_);
    Slot& s = slot(f.ray);
    const KdInterval box =
        rtu::sceneIntersection(s.ray, sections_.box, config_.tMaxClamp, config_.division);
    if (box.miss) {
      ++s.counts.boxMisses;
      f.boxMiss = true;
      u_.sintShader.push(now_, f);
    } else {
      f.node = 0;
      f.tMin = box.tMin;
      f.tMax = box.tMax;
      f.search = true;
      f.wptr = f.num = 0;
      u_.sintTarb.push(now_, f);
      u_.sintSs.push(now_, f);
    }
  }
}

// R1 simple_shade_unit.sv (issue side) and PRG/primary_ray_generator.sv.
void Pipe::shaderIssueAndPrg() {
  const int interval = config_.latency.prgInterval;
  const bool prgPhase = now_ % interval == 0;  // v0
  const bool sintPhase =
      now_ % config_.latency.sintInterval == config_.latency.sintInterval - 1;  // v2
  const bool idValid = u_.idFifo.valid(now_);
  const bool toSintValid = u_.prgFifo.valid(now_) && idValid;
  const bool toSintStall = toSintValid && (!sintPhase || sintUsStall_);
  const bool prgToShaderStall = toSintStall || !idValid;
  if (toSintValid && !toSintStall) {
    Flit f = u_.prgFifo.front();
    f.ray = u_.idFifo.front();
    u_.prgFifo.pop();
    u_.idFifo.pop();
    Slot& s = slot(f.ray);
    if (s.busy) throw std::logic_error("raypipe reference: a ray id given out twice");
    s = Slot{};
    s.stack.resize(static_cast<size_t>(config_.shortStackDepth));
    s.busy = true;
    s.index = f.index;
    s.ray = rays_[f.index].ray;
    results_[f.index].shaderInCycle = now_;
    ++inFlight_;
    maxInFlight_ = std::max(maxInFlight_, inFlight_);
    u_.sintPipe.accept(f);
    activity_.busy(Unit::Sint);
  } else if (u_.prgFifo.valid(now_)) {
    activity_.stall(Unit::Sint);
  }
  const bool prgUsStall = u_.prgPipe.usStall(prgToShaderStall, u_.prgFifo.numLeft());
  if (u_.prgPipe.outValid(now_)) u_.prgFifo.push(now_, u_.prgPipe.out(now_));
  if (issued_ < rays_.size() && prgPhase) {
    if (prgUsStall) {
      activity_.stall(Unit::Prg);
    } else {
      Flit f;
      f.index = static_cast<uint32_t>(issued_);
      results_[issued_].issueCycle = now_;
      ++issued_;
      u_.prgPipe.accept(f);
      activity_.busy(Unit::Prg);
    }
  }
}

void Pipe::tick() { u_.tick(now_); }

}  // namespace
}  // namespace raypipe_ref

RaypipeCycleRun runRaypipeCycles(const RaypipeConfig& config, const KdImage& image,
                                 const std::vector<RaypipeCycleRay>& rays,
                                 const RaypipePixelWriter& writer) {
  config.validate();
  if (config.traversalUnits != 1)
    throw std::invalid_argument(
        "raypipe.traversal_units: the per-cycle reference models one traversal unit (t5.sv)");
  if (config.cache != RaypipeCacheKind::BlockRam)
    throw std::invalid_argument("raypipe.cache: the per-cycle reference models the block RAMs");
  if (writer.vgaReadWindow)
    throw std::invalid_argument("the per-cycle reference does not model the VGA read window");
  raypipe_ref::Pipe pipe(config, image, rays);
  return pipe.run();
}

}  // namespace rtu
