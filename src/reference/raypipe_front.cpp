// The per-cycle reference of seed 001's ray pipe: the front of the pipe: the PRG (R1
// PRG/primary_ray_generator.sv: one pixel on v0, the 41-deep pipe, the 16-deep BRAM FIFO), the
// shader's issue side (simple_shade_unit.sv: a ray id from its FIFO) and SINT
// (RAYTRACER/scene_int/scene_int.sv: one ray on v2, the 18-deep pipe, three 18-deep FIFOs).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "reference/raypipe_top.h"

namespace rtu {
namespace raypipe_ref {

// R1 RAYTRACER/scene_int/scene_int.sv: the 18-cycle pipe and its three 18-deep FIFOs.
void Pipe::sceneIntersection() {
  const int sintInput = 2 + static_cast<int>(u_.trav.size());  // tarb's last input
  if (u_.tarb.accepted(sintInput)) u_.sintTarb.pop();
  if (u_.shaderArb.accepted(2)) u_.sintShader.pop();
  const bool dsStall = u_.tarb.stallUs(sintInput) || sintToSsStall_ || u_.shaderArb.stallUs(2);
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
    busy(Unit::Sint, f);
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
      busy(Unit::Prg, f, false);
    }
  }
}

}  // namespace raypipe_ref
}  // namespace rtu
