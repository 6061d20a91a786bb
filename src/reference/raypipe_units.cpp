// The per-cycle reference of seed 001's ray pipe: the units' construction, offers, input stalls
// and end of cycle (raypipe_units.h).
#include "reference/raypipe_units.h"

#include <stdexcept>

namespace rtu {
namespace raypipe_ref {
namespace {

std::vector<RegFifo<Flit>> three(const std::string& name, int depth) {
  std::vector<RegFifo<Flit>> fifos;
  for (int i = 0; i < 3; ++i) fifos.emplace_back(name + std::to_string(i), depth);
  return fifos;
}

}  // namespace

Units::Units(const RaypipeConfig& c)
    : prgPipe(c.latency.prg),
      prgFifo("prg", c.fifo.prg),
      idFifo("shader_ray_ids", 512),
      sintPipe(c.latency.sint),
      sintTarb("sint_tarb", c.fifo.sint),
      sintSs("sint_ss", c.fifo.sint),
      sintShader("sint_shader", c.fifo.sint),
      tarb("tarb", c.fifo.tarb),
      tcache("tcache", RaypipeCacheId::Tcache, c),
      rs0("raystore0", c.latency.memoryRead, c.fifo.memoryOut),
      leafFifo("trav_leaf", c.fifo.travLeaf),
      travPipe(c.latency.travMath),
      travFifo("trav_math", c.fifo.travMath),
      stackRead(three("ss_stack_read", 3)),
      restRead(three("ss_restart_read", 3)),
      restWrite(three("ss_restart_write", 3)),
      stackWrite("ss_stack_write", 3),
      stackPipe(2),
      restPipe(3),
      stackFifo("ss_stack", 3),
      notMissFifo("ss_restart", 4),
      missFifo("ss_miss", 4),
      larb("larb", c.fifo.larb),
      lcache("lcache", RaypipeCacheId::Lcache, c),
      icache("icache", RaypipeCacheId::Icache, c),
      rs1("raystore1", c.latency.memoryRead, c.fifo.memoryOut),
      intPipe(c.latency.intersection),
      intList("int_list", c.fifo.intList),
      intLarb("int_larb", c.fifo.intLarb),
      intShaderNumLeft(c.fifo.intShader),
      listPipe(4),
      listLast("list_last", 5),
      listHitPipe(2),
      listHitFifo("list_hit", 3),
      rs2("raystore2", c.latency.memoryRead, c.fifo.memoryOut),
      shaderArb("shader_arb", 2),
      shaderPipe(2),
      shaderData("shader_data", 3),
      pixelBuffer("pixel_buffer", c.fifo.pixelBuffer),
      dram(c.caches) {}

void Units::offerAll(int64_t now) {
  tarb.offer(0, stackFifo.empty() ? nullptr : &stackFifo.front());
  tarb.offer(1, notMissFifo.empty() ? nullptr : &notMissFifo.front());
  tarb.offer(2, travTarbValid ? &travTarb : nullptr);
  tarb.offer(3, sintTarb.empty() ? nullptr : &sintTarb.front());
  larb.offer(0, travLarbValid ? &travLarb : nullptr);
  larb.offer(1, intLarb.valid(now) ? &intLarb.front() : nullptr);
  shaderArb.offer(0, rs2.fifo.empty() ? nullptr : &rs2.fifo.front());
  shaderArb.offer(1, nullptr);
  shaderArb.offer(2, sintShader.empty() ? nullptr : &sintShader.front());
  shaderArb.offer(3, missFifo.empty() ? nullptr : &missFifo.front());
  travSsNext = travSs;
  travTarbNext = travTarb;
  travLarbNext = travLarb;
  travListNext = travList;
  toSsValidNext = toSsValid;
  toSsNext = toSs;
}

bool Units::travToSsStall() const {
  if (!travSsValid) return false;
  const Flit& f = travSs;
  const int code =
      (f.popReq ? 8 : 0) | (f.maxsceneReq ? 4 : 0) | (f.pushReq ? 2 : 0) | (f.restReq ? 1 : 0);
  switch (code) {
    case 8: return f.num == 0 ? restRead[0].full() : stackRead[0].full();
    case 4: return restWrite[0].full();
    case 2: return stackWrite.full();
    case 3: return stackWrite.full() || restWrite[0].full();
    default:
      throw std::logic_error("raypipe reference: TRAV sent the shortstack the request " +
                             std::to_string(code));
  }
}

bool Units::listToSsStall() const {
  if (!toSsValid) return false;
  const bool restOk = toSs.num == 0 && !restRead[2].full();
  const bool stackOk = toSs.num != 0 && !stackRead[2].full();
  return !(restOk || stackOk);
}

void Units::tick(int64_t now) {
  prgPipe.tick(now);
  prgFifo.tick(now);
  idFifo.tick(now);
  sintPipe.tick(now);
  sintTarb.tick(now);
  sintSs.tick(now);
  sintShader.tick(now);
  tarb.tick(now);
  // the miss handlers see the arbiter's doneRead of the cycle, the arbiter their readReq
  std::array<bool, kRaypipeDramPorts> asking{};
  std::array<uint32_t, kRaypipeDramPorts> bytes{};
  for (const CacheRead* c : {&icache, &tcache, &lcache}) {
    asking[static_cast<size_t>(c->port())] = c->asking();
    bytes[static_cast<size_t>(c->port())] = c->lineBytes();
  }
  for (CacheRead* c : {&icache, &tcache, &lcache}) c->tick(now, dram);
  dram.tick(now, asking, bytes);
  rs0.tick(now);
  leafFifo.tick(now);
  travPipe.tick(now);
  travFifo.tick(now);
  travSsValid = travSsValidNext;
  travTarbValid = travTarbValidNext;
  travLarbValid = travLarbValidNext;
  travListValid = travListValidNext;
  travSs = travSsNext;
  travTarb = travTarbNext;
  travLarb = travLarbNext;
  travList = travListNext;
  for (auto& f : stackRead) f.tick(now);
  for (auto& f : restRead) f.tick(now);
  for (auto& f : restWrite) f.tick(now);
  stackWrite.tick(now);
  stackPipe.tick(now);
  restPipe.tick(now);
  stackFifo.tick(now);
  notMissFifo.tick(now);
  missFifo.tick(now);
  larb.tick(now);
  rs1.tick(now);
  intPipe.tick(now);
  intList.tick(now);
  intLarb.tick(now);
  listPipe.tick(now);
  listLast.tick(now);
  listHitPipe.tick(now);
  listHitFifo.tick(now);
  toSsValid = toSsValidNext;
  toSs = toSsNext;
  rs2.tick(now);
  shaderArb.tick(now);
  shaderPipe.tick(now);
  shaderData.tick(now);
  pixelBuffer.tick(now);
}

std::vector<RaypipeFifoPeak> Units::fifoPeaks() const {
  std::vector<const FifoStats*> all = {
      &prgFifo,     &idFifo,     &sintTarb,   &sintSs,      &sintShader,  &tarb.out(),
      &tcache.fifo, &rs0.fifo,   &leafFifo,   &travFifo,    &stackWrite,  &stackFifo,
      &notMissFifo, &missFifo,   &larb.out(), &lcache.fifo, &icache.fifo, &rs1.fifo,
      &intList,     &intLarb,    &listLast,   &listHitFifo, &rs2.fifo,    &shaderArb.out(),
      &shaderData,  &pixelBuffer};
  for (const auto& f : stackRead) all.push_back(&f);
  for (const auto& f : restRead) all.push_back(&f);
  for (const auto& f : restWrite) all.push_back(&f);
  std::vector<RaypipeFifoPeak> peaks;
  for (const FifoStats* f : all) peaks.push_back(RaypipeFifoPeak{f->name(), f->depth(), f->peak()});
  return peaks;
}

std::vector<RaypipeCacheCounts> Units::cacheCounts() const {
  return {tcache.counts(), lcache.counts(), icache.counts()};
}

}  // namespace raypipe_ref
}  // namespace rtu
