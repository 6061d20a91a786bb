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

std::string suffix(int i) { return i == 0 ? "" : "_" + std::to_string(i); }

}  // namespace

TravUnit::TravUnit(const RaypipeConfig& c, int i)
    : tcache("tcache" + suffix(i), i == 0 ? RaypipeCacheId::Tcache : RaypipeCacheId::Tcache1, c),
      rs0("raystore0" + suffix(i), c.latency.memoryRead, c.fifo.memoryOut),
      leafFifo("trav_leaf" + suffix(i), c.fifo.travLeaf),
      travPipe(c.latency.travMath),
      travFifo("trav_math" + suffix(i), c.fifo.travMath),
      stackWrite("ss_stack_write" + suffix(i), 3) {}

// The registers' next values are their current ones unless the cycle sets them.
void TravUnit::keepRegisters() {
  ssNext = ss;
  tarbOutNext = tarbOut;
  larbOutNext = larbOut;
  listNext = list;
}

// The cycle's end, but for the tcache (Units::tick steps the caches with the arbiter).
void TravUnit::tick(int64_t now) {
  rs0.tick(now);
  leafFifo.tick(now);
  travPipe.tick(now);
  travFifo.tick(now);
  stackWrite.tick(now);
  ssValid = ssValidNext;
  tarbValid = tarbValidNext;
  larbValid = larbValidNext;
  listValid = listValidNext;
  ss = ssNext;
  tarbOut = tarbOutNext;
  larbOut = larbOutNext;
  list = listNext;
}

Units::Units(const RaypipeConfig& c)
    : prgPipe(c.latency.prg),
      prgFifo("prg", c.fifo.prg),
      idFifo("shader_ray_ids", 512),
      sintPipe(c.latency.sint),
      sintTarb("sint_tarb", c.fifo.sint),
      sintSs("sint_ss", c.fifo.sint),
      sintShader("sint_shader", c.fifo.sint),
      tarb("tarb", c.fifo.tarb, 3 + c.traversalUnits, c.traversalUnits),
      stackRead(three("ss_stack_read", 3)),
      restRead(three("ss_restart_read", 3)),
      restWrite(three("ss_restart_write", 3)),
      stackPipe(2),
      restPipe(3),
      stackFifo("ss_stack", 3),
      notMissFifo("ss_restart", 4),
      missFifo("ss_miss", 4),
      larb("larb", c.fifo.larb, 1 + c.traversalUnits),
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
      dram(c.caches) {
  trav.reserve(static_cast<size_t>(c.traversalUnits));
  for (int i = 0; i < c.traversalUnits; ++i) trav.emplace_back(c, i);
}

void Units::offerAll(int64_t now) {
  const int units = static_cast<int>(trav.size());
  tarb.offer(0, stackFifo.empty() ? nullptr : &stackFifo.front());
  tarb.offer(1, notMissFifo.empty() ? nullptr : &notMissFifo.front());
  for (int i = 0; i < units; ++i) {
    TravUnit& u = trav[static_cast<size_t>(i)];
    tarb.offer(2 + i, u.tarbValid ? &u.tarbOut : nullptr);
    larb.offer(i, u.larbValid ? &u.larbOut : nullptr);
    u.keepRegisters();
  }
  tarb.offer(2 + units, sintTarb.empty() ? nullptr : &sintTarb.front());
  larb.offer(units, intLarb.valid(now) ? &intLarb.front() : nullptr);
  shaderArb.offer(0, rs2.fifo.empty() ? nullptr : &rs2.fifo.front());
  shaderArb.offer(1, nullptr);
  shaderArb.offer(2, sintShader.empty() ? nullptr : &sintShader.front());
  shaderArb.offer(3, missFifo.empty() ? nullptr : &missFifo.front());
  toSsValidNext = toSsValid;
  toSsNext = toSs;
}

// Traversal unit i's request: into the request and write FIFOs of its port i.
bool Units::travToSsStall(size_t i) const {
  const TravUnit& u = trav[i];
  if (!u.ssValid) return false;
  const Flit& f = u.ss;
  const int code =
      (f.popReq ? 8 : 0) | (f.maxsceneReq ? 4 : 0) | (f.pushReq ? 2 : 0) | (f.restReq ? 1 : 0);
  switch (code) {
    case 8: return f.num == 0 ? restRead[i].full() : stackRead[i].full();
    case 4: return restWrite[i].full();
    case 2: return u.stackWrite.full();
    case 3: return u.stackWrite.full() || restWrite[i].full();
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
  std::array<CacheRead*, kRaypipeDramPorts> caches{&icache, &lcache, &trav[0].tcache};
  if (trav.size() > 1) caches[3] = &trav[1].tcache;
  std::array<bool, kRaypipeDramPorts> asking{};
  std::array<uint32_t, kRaypipeDramPorts> bytes{};
  for (const CacheRead* c : caches) {
    if (!c) continue;
    asking[static_cast<size_t>(c->port())] = c->asking();
    bytes[static_cast<size_t>(c->port())] = c->lineBytes();
  }
  for (CacheRead* c : caches)
    if (c) c->tick(now, dram);
  dram.tick(now, asking, bytes);
  for (TravUnit& u : trav) u.tick(now);
  for (auto& f : stackRead) f.tick(now);
  for (auto& f : restRead) f.tick(now);
  for (auto& f : restWrite) f.tick(now);
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
  std::vector<const FifoStats*> all = {&prgFifo, &idFifo, &sintTarb, &sintSs, &sintShader};
  for (size_t i = 0; i < trav.size(); ++i) {
    const TravUnit& t = trav[i];
    all.insert(all.end(), {&tarb.out(static_cast<int>(i)), &t.tcache.fifo, &t.rs0.fifo, &t.leafFifo,
                           &t.travFifo});
  }
  for (const TravUnit& t : trav) all.push_back(&t.stackWrite);
  all.insert(all.end(), {&stackFifo, &notMissFifo, &missFifo, &larb.out(), &lcache.fifo,
                         &icache.fifo, &rs1.fifo, &intList, &intLarb, &listLast, &listHitFifo,
                         &rs2.fifo, &shaderArb.out(), &shaderData, &pixelBuffer});
  for (const auto& f : stackRead) all.push_back(&f);
  for (const auto& f : restRead) all.push_back(&f);
  for (const auto& f : restWrite) all.push_back(&f);
  std::vector<RaypipeFifoPeak> peaks;
  for (const FifoStats* f : all) peaks.push_back(RaypipeFifoPeak{f->name(), f->depth(), f->peak()});
  return peaks;
}

std::vector<RaypipeCacheCounts> Units::cacheCounts() const {
  std::vector<RaypipeCacheCounts> counts;
  for (const TravUnit& t : trav) counts.push_back(t.tcache.counts());
  counts.push_back(lcache.counts());
  counts.push_back(icache.counts());
  return counts;
}

}  // namespace raypipe_ref
}  // namespace rtu
