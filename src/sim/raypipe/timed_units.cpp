// The timed model of seed 001's ray pipe: its channels' construction and FIFO peaks
// (timed_units.h).
#include "sim/raypipe/timed_units.h"

namespace rtu {
namespace raypipe_timed {
namespace {

std::array<Fifo, 3> three(const std::string& name) {
  return {Fifo(name + "0", 3, kRegister), Fifo(name + "1", 3, kRegister),
          Fifo(name + "2", 3, kRegister)};
}

}  // namespace

Channels::Channels(const RaypipeConfig& c)
    : prgPipe(c.latency.prg),
      prgFifo("prg", c.fifo.prg, kShowAhead),
      idFifo("shader_ray_ids", 512, kShowAhead),
      sintPipe(c.latency.sint),
      sintTarb("sint_tarb", c.fifo.sint, kRegister),
      sintSs("sint_ss", c.fifo.sint, kRegister),
      sintShader("sint_shader", c.fifo.sint, kRegister),
      tarb("tarb", c.fifo.tarb, kShowAhead),
      tcache("tcache", c.latency.memoryRead, c.fifo.memoryOut),
      rs0("raystore0", c.latency.memoryRead, c.fifo.memoryOut),
      leafFifo("trav_leaf", c.fifo.travLeaf, kRegister),
      travPipe(c.latency.travMath),
      travFifo("trav_math", c.fifo.travMath, kRegister),
      stackRead(three("ss_stack_read")),
      restRead(three("ss_restart_read")),
      restWrite(three("ss_restart_write")),
      stackWrite("ss_stack_write", 3, kRegister),
      stackPipe(2),
      restPipe(3),
      stackFifo("ss_stack", 3, kRegister),
      notMissFifo("ss_restart", 4, kRegister),
      missFifo("ss_miss", 4, kRegister),
      larb("larb", c.fifo.larb, kShowAhead),
      lcache("lcache", c.latency.memoryRead, c.fifo.memoryOut),
      icache("icache", c.latency.memoryRead, c.fifo.memoryOut),
      rs1("raystore1", c.latency.memoryRead, c.fifo.memoryOut),
      intPipe(c.latency.intersection),
      intList("int_list", c.fifo.intList, kShowAhead),
      intLarb("int_larb", c.fifo.intLarb, kShowAhead),
      intShaderNumLeft(c.fifo.intShader),
      listPipe(4),
      listLast("list_last", 5, kRegister),
      listHitPipe(2),
      listHitFifo("list_hit", 3, kRegister),
      rs2("raystore2", c.latency.memoryRead, c.fifo.memoryOut),
      shaderArb("shader_arb", 2, kRegister),
      shaderPipe(2),
      shaderData("shader_data", 3, kRegister),
      pixelBuffer("pixel_buffer", c.fifo.pixelBuffer, kRegister) {}

std::vector<Fifo*> Channels::fifos() {
  std::vector<Fifo*> all = {
      &prgFifo,     &sintTarb,    &sintSs,          &sintShader, &tarb.out(),
      &tcache.fifo, &rs0.fifo,    &leafFifo,        &travFifo,   &stackWrite,
      &stackFifo,   &notMissFifo, &missFifo,        &larb.out(), &lcache.fifo,
      &icache.fifo, &rs1.fifo,    &intList,         &intLarb,    &listLast,
      &listHitFifo, &rs2.fifo,    &shaderArb.out(), &shaderData, &pixelBuffer};
  for (auto* group : {&stackRead, &restRead, &restWrite})
    for (Fifo& f : *group) all.push_back(&f);
  return all;
}

std::vector<RaypipeFifoPeak> Channels::peaks() {
  std::vector<RaypipeFifoPeak> peaks;
  for (const Fifo* f : fifos()) peaks.push_back(RaypipeFifoPeak{f->name(), f->depth(), f->peak()});
  peaks.insert(peaks.begin() + 1, RaypipeFifoPeak{idFifo.name(), idFifo.depth(), idFifo.peak()});
  return peaks;
}

}  // namespace raypipe_timed
}  // namespace rtu
