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

std::string suffix(int i) { return i == 0 ? "" : "_" + std::to_string(i); }

}  // namespace

TravUnit::TravUnit(const RaypipeConfig& c, int i, DramArbiter& dram)
    : tcache("tcache" + suffix(i), i == 0 ? RaypipeCacheId::Tcache : RaypipeCacheId::Tcache1, c,
             dram),
      rs0("raystore0" + suffix(i), c.latency.memoryRead, c.fifo.memoryOut),
      leafFifo("trav_leaf" + suffix(i), c.fifo.travLeaf, kRegister),
      travPipe(c.latency.travMath),
      travFifo("trav_math" + suffix(i), c.fifo.travMath, kRegister) {}

Channels::Channels(const RaypipeConfig& c)
    : dram(c.caches),
      prgPipe(c.latency.prg),
      prgFifo("prg", c.fifo.prg, kShowAhead),
      idFifo("shader_ray_ids", 512, kShowAhead),
      sintPipe(c.latency.sint),
      sintTarb("sint_tarb", c.fifo.sint, kRegister),
      sintSs("sint_ss", c.fifo.sint, kRegister),
      sintShader("sint_shader", c.fifo.sint, kRegister),
      tarb("tarb", c.fifo.tarb, kShowAhead, 3 + c.traversalUnits, c.traversalUnits),
      stackRead(three("ss_stack_read")),
      restRead(three("ss_restart_read")),
      restWrite(three("ss_restart_write")),
      stackPipe(2),
      restPipe(3),
      stackFifo("ss_stack", 3, kRegister),
      notMissFifo("ss_restart", 4, kRegister),
      missFifo("ss_miss", 4, kRegister),
      larb("larb", c.fifo.larb, kShowAhead, 1 + c.traversalUnits),
      lcache("lcache", RaypipeCacheId::Lcache, c, dram),
      icache("icache", RaypipeCacheId::Icache, c, dram),
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
      shaderArb("shader_arb", 2, kRegister, 4),
      shaderPipe(2),
      shaderData("shader_data", 3, kRegister),
      pixelBuffer("pixel_buffer", c.fifo.pixelBuffer, kRegister) {
  trav.reserve(static_cast<size_t>(c.traversalUnits));  // the FIFOs' places are kept (fifos())
  stackWrite.reserve(static_cast<size_t>(c.traversalUnits));
  for (int i = 0; i < c.traversalUnits; ++i) {
    trav.emplace_back(c, i, dram);
    stackWrite.emplace_back("ss_stack_write" + suffix(i), 3, kRegister);
  }
}

std::vector<Fifo*> Channels::fifos() {
  std::vector<Fifo*> all = {&prgFifo, &sintTarb, &sintSs, &sintShader};
  for (size_t i = 0; i < trav.size(); ++i) {
    TravUnit& t = trav[i];
    all.insert(all.end(), {&tarb.out(static_cast<int>(i)), &t.tcache.read.fifo, &t.rs0.fifo,
                           &t.leafFifo, &t.travFifo});
  }
  for (Fifo& f : stackWrite) all.push_back(&f);
  all.insert(all.end(), {&stackFifo, &notMissFifo, &missFifo, &larb.out(), &lcache.read.fifo,
                         &icache.read.fifo, &rs1.fifo, &intList, &intLarb, &listLast, &listHitFifo,
                         &rs2.fifo, &shaderArb.out(), &shaderData, &pixelBuffer});
  for (auto* group : {&stackRead, &restRead, &restWrite})
    for (Fifo& f : *group) all.push_back(&f);
  return all;
}

std::vector<RaypipeCacheCounts> Channels::cacheCounts() const {
  std::vector<RaypipeCacheCounts> counts;
  for (const TravUnit& t : trav) counts.push_back(t.tcache.counts());
  counts.push_back(lcache.counts());
  counts.push_back(icache.counts());
  return counts;
}

std::vector<RaypipeFifoPeak> Channels::peaks() {
  std::vector<RaypipeFifoPeak> peaks;
  for (const Fifo* f : fifos()) peaks.push_back(RaypipeFifoPeak{f->name(), f->depth(), f->peak()});
  peaks.insert(peaks.begin() + 1, RaypipeFifoPeak{idFifo.name(), idFifo.depth(), idFifo.peak()});
  return peaks;
}

}  // namespace raypipe_timed
}  // namespace rtu
