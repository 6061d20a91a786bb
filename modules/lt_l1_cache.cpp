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
      hitCycles_(config.hitLatency),
      hitDelay_(time.cycles(config.hitLatency)),
      lineRead_(config.lineBytes) {
  socket.bind(*this);
}

void LtL1Cache::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  const uint32_t word = static_cast<uint32_t>(trans.get_address() / 4);
  const uint64_t cycle = time_.cycleAt(delay);
  const L1Lookup lookup = timing_.lookup(word, cycle);
  if (lookup.hit && lookup.cycle == cycle + hitCycles_)
    delay += hitDelay_;  // the common hit, without converting cycles to time
  else
    delay = time_.delayTo(lookup.hit ? lookup.cycle : fetch(word, lookup));
  serveWordRead(words_, trans);
}

uint64_t LtL1Cache::fetch(uint32_t word, const L1Lookup& miss) {
  const uint64_t filled =
      lineRead_(next, time_, miss.lineAddress, timing_.array().config().lineBytes, miss.cycle);
  return timing_.fill(word, filled);
}

unsigned int LtL1Cache::transport_dbg(tlm::tlm_generic_payload& trans) {
  serveWordRead(words_, trans);
  return trans.is_response_ok() ? trans.get_data_length() : 0;
}

}  // namespace rtu
