// The timed model of seed 001's ray pipe: the shader's return side (simple_shade_unit.sv: its
// 4-input arbiter into a 2-entry FIFO, the 2-cycle VS pipe, the 3-entry ray-data FIFO, the ray id
// freed) and the pixel buffer (t5.sv, 20 deep) with its SRAM writer. Timing rules: the arbiter as
// rotating_arbiter.h ([0] list hit, [1] shadow hit, [2] SINT's box miss, [3] the shortstack's
// miss); its head goes on unless the pipe stalls or the shader is still in is_init, writing the
// ray id back; the ray-data FIFO's head leaves (the pixel's exit) when the pixel buffer is not
// full; the writer takes a pixel every cycle the buffer holds one and the VGA reader does not hold
// the SRAM (vga_window.h, when RaypipePixelWriter::vgaReadWindow is set).
#include <stdexcept>
#include <string>

#include "sim/raypipe/timed_pipe.h"

namespace rtu {
namespace raypipe_timed {

void TimedPipe::shaderReturn() {
  const RotatingArbiter<RayToken>::Offers offers = {
      c_.rs2.fifo.shown(now_) ? &c_.rs2.fifo.front() : nullptr, nullptr,
      c_.sintShader.shown(now_) ? &c_.sintShader.front() : nullptr,
      c_.missFifo.shown(now_) ? &c_.missFifo.front() : nullptr};
  if (offers[0] || offers[2] || offers[3] || c_.shaderArb.holds())
    if (const RayToken* g = c_.shaderArb.arbitrate(now_, offers)[0]) busy(Unit::ShaderArb, *g);
  const bool pbFull = c_.pixelBuffer.full(now_);
  const bool dataShown = c_.shaderData.shown(now_);
  const bool pipeUsStall =
      c_.shaderPipe.usStall(now_, pbFull && dataShown, c_.shaderData.numLeft(now_));
  if (c_.shaderArb.out().shown(now_)) {
    if (pipeUsStall || now_ < initEnd_) {
      stall(Unit::ShaderReturn);
    } else {
      RayToken t = c_.shaderArb.out().pop(now_);
      RayRecord& r = record(t.ray);
      if (!r.busy)
        throw std::logic_error("raypipe timed model: a result for the free ray id " +
                               std::to_string(t.ray) + " at cycle " + std::to_string(now_));
      RaypipeCycleResult& result = results_[r.index];
      result.hit = t.isHit;
      result.boxMiss = t.boxMiss;
      if (t.isHit) {
        result.t = t.t;
        result.u = t.u;
        result.v = t.v;
        result.primitive = t.tri;
      }
      if (!t.isHit && !t.boxMiss && r.hitCur) ++staleListHits_;
      result.counts = r.counts;
      result.rayId = t.ray;
      r.busy = false;
      --inFlight_;
      t.index = r.index;
      c_.shaderPipe.accept(now_, t);
      c_.idFifo.push(now_, t.ray);  // rayID_wrreq: the id is free again
      busy(Unit::ShaderReturn, t);
    }
  }
  if (c_.shaderPipe.exiting(now_)) c_.shaderData.push(now_, c_.shaderPipe.take(now_));
  if (dataShown && !pbFull) {
    const RayToken t = c_.shaderData.pop(now_);
    RaypipeCycleResult& result = results_[t.index];
    if (result.exitCycle >= 0) throw std::logic_error("raypipe timed model: a pixel left twice");
    result.exitCycle = now_;
    c_.pixelBuffer.push(now_, t);
  }
  // the SRAM writer: one pixel a cycle while the buffer holds one, unless the VGA reader holds the
  // SRAM (then the group looks again next cycle)
  if (!c_.pixelBuffer.shown(now_)) return;
  if (vgaReadWindow_ && vga_.reading(now_)) {
    ++writerWaits_;
    stall(Unit::PixelWriter);
    calendar_.book(kShader, now_ + 1, now_);
    return;
  }
  const RayToken t = c_.pixelBuffer.pop(now_);
  lastWrite_ = now_;
  ++written_;
  busy(Unit::PixelWriter, t);
}

}  // namespace raypipe_timed
}  // namespace rtu
