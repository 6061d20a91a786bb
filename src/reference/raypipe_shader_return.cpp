// The per-cycle reference of seed 001's ray pipe: the shader's return side (R1
// RAYTRACER/shader/simple_shade_unit.sv: its 4-input arbiter, VS pipe 2, ray-data FIFO 3, the ray
// id freed) and the pixel buffer (DEMOS/t5.sv, 20 deep) with its SRAM writer and the VGA
// reader's window (raypipe_vga.h).
#include <algorithm>
#include <stdexcept>
#include <string>

#include "reference/raypipe_top.h"

namespace rtu {
namespace raypipe_ref {

// R1 RAYTRACER/shader/simple_shade_unit.sv (return side) and DEMOS/t5.sv's pixel buffer.
void Pipe::shaderReturn(size_t& exited, size_t& written) {
  u_.shaderArb.arbitrate(now_);
  if (const Flit* g = u_.shaderArb.granted()) busy(Unit::ShaderArb, *g);
  const bool pbFull = u_.pixelBuffer.full();
  const bool dataRe = !pbFull && !u_.shaderData.empty();
  const bool pipeDsStall = pbFull && !u_.shaderData.empty();
  const bool pipeUsStall = u_.shaderPipe.usStall(pipeDsStall, u_.shaderData.numLeft());
  auto& arbOut = u_.shaderArb.out();
  const bool arbValid = arbOut.valid(now_);
  const bool isInit = now_ < initEnd_;  // arb_stall_ds = valid & (us_stall | is_init)
  if (arbValid && (pipeUsStall || isInit)) activity_.stall(Unit::ShaderReturn);
  if (arbValid && !pipeUsStall && !isInit) {
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
    busy(Unit::ShaderReturn, out);
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
  // The SRAM writer: one pixel a cycle while the buffer holds one, unless the VGA reader holds
  // the SRAM.
  const bool vgaReads = writer_.vgaReadWindow && vga_.reading();
  if (!u_.pixelBuffer.empty()) {
    if (vgaReads) {
      ++writerWaits_;
      activity_.stall(Unit::PixelWriter);
    } else {
      u_.pixelBuffer.pop();
      lastWrite_ = now_;
      ++written;
      busy(Unit::PixelWriter, u_.pixelBuffer.front());
    }
  }
  if (writer_.vgaReadWindow) vga_.tick();
}

}  // namespace raypipe_ref
}  // namespace rtu
