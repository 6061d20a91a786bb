#include "lt_l1_cache.h"

#include "lt_rom.h"

namespace rtu {

LtL1Cache::LtL1Cache(sc_core::sc_module_name name, const CacheConfig& config, SvoMemory words,
                     const LtTime& time)
    : sc_core::sc_module(name),
      socket("socket"),
      next("next"),
      words_(words),
      time_(time),
      timing_(config),
      lineRead_(config.lineBytes) {
  socket.register_b_transport(this, &LtL1Cache::b_transport);
}

void LtL1Cache::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  const uint32_t word = static_cast<uint32_t>(trans.get_address() / 4);
  const L1Lookup lookup = timing_.lookup(word, time_.cycleAt(delay));
  const uint64_t ready =
      lookup.hit ? lookup.cycle : timing_.fill(word, lineRead_(next, time_, lookup.lineAddress,
                                         timing_.array().config().lineBytes, lookup.cycle));
  delay = time_.delayTo(ready);
  serveWordRead(words_, trans);
}

}  // namespace rtu
