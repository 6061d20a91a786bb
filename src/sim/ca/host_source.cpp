#include "sim/ca/host_source.h"

#include <algorithm>
#include <utility>

namespace rtu {

HostSource::HostSource(sc_core::sc_module_name name, const CycleClock& clock, DecisionPump& pump,
                       RecordSource records, HostLinkConfig link, uint64_t lookAhead)
    : sc_core::sc_module(name),
      Agent(pump),
      clock_(clock),
      records_(std::move(records)),
      pacer_(link),
      lookAhead_(lookAhead),
      wake_(clock) {
  validate(link, "host input");
}

void HostSource::bind(TransferChannel<HostPayload>& out) { out_ = &out; }

void HostSource::end_of_elaboration() {
  // Runs at the start of simulation and whenever simulated time catches up with the next offer.
  spawnMethod("offer", [this] { pump().runWith(*this); }, {&wake_.event()});
}

void HostSource::decide() {
  if (out_->collectTaken()) {
    ++next_;
    allowedFrom_ = pacer_.nextAllowed(out_->lastTransfer());
    drawnOffer_ = kNeverCycle;
  }
  if (out_->offering() || next_ == records_.size()) return;
  const uint64_t cycle = offerCycle();
  if (cycle > clock_.now() + lookAhead_) {
    wake_.at(cycle - lookAhead_ / 2);  // then it offers records for about half the look-ahead
    return;
  }
  out_->offer(HostPayload{PayloadIds::plain(next_), records_[next_]}, cycle);
}

// The link's next slot; a randomly inactive link offers in the first active cycle from there
// (one draw per cycle).
uint64_t HostSource::offerCycle() {
  if (!pacer_.random()) return allowedFrom_;
  if (drawnOffer_ == kNeverCycle) {
    drawnOffer_ = allowedFrom_;
    while (!pacer_.drawActive()) ++drawnOffer_;
  }
  return drawnOffer_;
}

}  // namespace rtu
