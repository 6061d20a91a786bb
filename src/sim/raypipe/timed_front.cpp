// The timed model of seed 001's ray pipe: the front (PRG/primary_ray_generator.sv: a pixel on v0,
// the 41-deep pipe, the 16-deep BRAM FIFO; simple_shade_unit.sv's issue side: a ray id from its
// FIFO; scene_int.sv: one ray on v2, the 18-deep pipe, three 18-deep register FIFOs whose least
// free space is its credit).
#include <algorithm>
#include <stdexcept>

#include "sim/raypipe/timed_pipe.h"

namespace rtu {
namespace raypipe_timed {

void TimedPipe::sceneIntersection() {
  const int sintInput = 2 + static_cast<int>(c_.trav.size());  // tarb's last input
  if (c_.tarb.accepted(sintInput, now_)) c_.sintTarb.pop(now_);
  if (c_.shaderArb.accepted(2, now_)) c_.sintShader.pop(now_);
  if (!c_.sintPipe.any() && !c_.sintTarb.any() && !c_.sintSs.any() && !c_.sintShader.any()) {
    sintUsStall_ = false;
    return;
  }
  const bool dsStall = c_.tarb.stallUs(sintInput, now_) || sintToSsStall_ ||
                       c_.shaderArb.stallUs(2, now_);
  const int left =
      std::min({c_.sintTarb.numLeft(now_), c_.sintSs.numLeft(now_), c_.sintShader.numLeft(now_)});
  sintUsStall_ = c_.sintPipe.usStall(now_, dsStall, left);
  if (!c_.sintPipe.exiting(now_)) return;
  RayToken t = c_.sintPipe.take(now_);
  RayRecord& r = record(t.ray);
  const KdInterval box = rtu::sceneIntersection(rays_[t.index].ray, sections_.box,
                                                config_.tMaxClamp, config_.division);
  if (box.miss) {
    ++r.counts.boxMisses;
    t.boxMiss = true;
    c_.sintShader.push(now_, t);
    return;
  }
  t.node = 0;
  t.tMin = box.tMin;
  t.tMax = box.tMax;
  t.search = true;
  c_.sintTarb.push(now_, t);
  c_.sintSs.push(now_, t);
}

void TimedPipe::shaderIssueAndPrg() {
  const auto& lat = config_.latency;
  // SINT stalled in every cycle since the last call from the one the PRG FIFO's head was shown
  if (c_.prgFifo.any())
    stalls(Unit::Sint, std::max(lastPrgCall_ + 1, c_.prgFifo.headShownFrom()), now_);
  if (prgBlocked_) {
    const int64_t interval = lat.prgInterval;  // the v0 cycles after the last call, before now
    if (trace_)
      for (int64_t v0 = (lastPrgCall_ / interval + 1) * interval; v0 < now_; v0 += interval)
        stalls(Unit::Prg, v0, v0 + 1);
    else
      stall_[static_cast<size_t>(Unit::Prg)] += (now_ - 1) / interval - lastPrgCall_ / interval;
  }
  lastPrgCall_ = now_;
  const bool idShown = c_.idFifo.shown(now_);
  const bool prgShown = c_.prgFifo.shown(now_);
  const bool toSintValid = prgShown && idShown;
  const bool toSintStall =
      toSintValid && (now_ % lat.sintInterval != lat.sintInterval - 1 || sintUsStall_);
  if (toSintValid && !toSintStall) {
    RayToken t = c_.prgFifo.pop(now_);
    t.ray = c_.idFifo.pop(now_);
    RayRecord& r = record(t.ray);
    if (r.busy) throw std::logic_error("raypipe timed model: a ray id given out twice");
    r = RayRecord{};
    r.busy = true;
    r.index = t.index;
    results_[t.index].shaderInCycle = now_;
    maxInFlight_ = std::max(maxInFlight_, ++inFlight_);
    c_.sintPipe.accept(now_, t);
    busy(Unit::Sint, t);
  } else if (prgShown) {
    stall(Unit::Sint);
  }
  const bool prgToShaderStall = toSintStall || !idShown;
  const bool prgUsStall = c_.prgPipe.usStall(now_, prgToShaderStall, c_.prgFifo.numLeft(now_));
  if (c_.prgPipe.exiting(now_)) c_.prgFifo.push(now_, c_.prgPipe.take(now_));
  if (issued_ >= rays_.size() || now_ % lat.prgInterval != 0) return;
  if (prgUsStall) {
    stall(Unit::Prg);
    return;
  }
  RayToken t;
  t.index = static_cast<uint32_t>(issued_++);
  results_[t.index].issueCycle = now_;
  c_.prgPipe.accept(now_, t);
  busy(Unit::Prg, t, false);
}

}  // namespace raypipe_timed
}  // namespace rtu
