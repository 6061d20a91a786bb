#include "sim/lt/lt_l1_cache.h"

#include <stdexcept>
#include <string>

#include "sim/lt/lt_word_read.h"

namespace rtu {

namespace {

uint32_t checkedAccess(uint32_t accessBytes, const CacheConfig& config) {
  if (accessBytes < 4 || (accessBytes & (accessBytes - 1)) != 0 || accessBytes > config.lineBytes)
    throw std::invalid_argument("an L1 of " + std::to_string(config.lineBytes) +
                                "-byte lines cannot serve accesses of " +
                                std::to_string(accessBytes) + " bytes");
  return accessBytes;
}

}  // namespace

LtL1Cache::LtL1Cache(sc_core::sc_module_name name, const CacheConfig& config, uint32_t accessBytes,
                     WordMemory words, const LtTime& time)
    : sc_core::sc_module(name),
      socket("socket"),
      next("next"),
      words_(words),
      time_(time),
      timing_(config, nullptr, time.periodPicoseconds()),
      hitPicoseconds_(config.hitLatency * time.periodPicoseconds()),
      hitDelay_(time.cycles(config.hitLatency)),
      accessBytes_(checkedAccess(accessBytes, config)),
      lineBytes_(config.lineBytes),
      lineRead_(config.lineBytes) {
  socket.bind(*this);
}

// The tag store counts picoseconds since the start, the unit of the annotated delay, so that a
// hit (the common case) converts nothing: it adds the hit latency to the delay.
void LtL1Cache::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  if (!acceptAccess(trans, accessBytes_)) return;
  const uint32_t word = static_cast<uint32_t>(trans.get_address() / 4);
  const uint64_t at = time_.nowPicoseconds() + delay.value();
  const L1Lookup lookup = timing_.lookup(word, at);
  if (!lookup.hit)
    delay = fetch(word, lookup.lineAddress, delay + hitDelay_);
  else if (lookup.cycle == at + hitPicoseconds_)
    delay += hitDelay_;
  else
    delay = time_.delayToPicoseconds(lookup.cycle);  // the line is still in flight
  serveWordRead(words_, trans);
}

sc_core::sc_time LtL1Cache::fetch(uint32_t word, uint64_t lineAddress, sc_core::sc_time request) {
  const sc_core::sc_time filled = lineRead_(next, lineAddress, lineBytes_, request);
  timing_.fill(word, time_.nowPicoseconds() + filled.value());
  return filled;
}

unsigned int LtL1Cache::transport_dbg(tlm::tlm_generic_payload& trans) {
  if (acceptWordRead(trans, lineBytes_)) serveWordRead(words_, trans);
  return trans.is_response_ok() ? trans.get_data_length() : 0;
}

}  // namespace rtu
