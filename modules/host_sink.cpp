#include "host_sink.h"

namespace rtu {

HostSink::HostSink(sc_core::sc_module_name name, const CycleClock& clock, uint64_t expected,
                   HostLinkConfig link)
    : sc_core::sc_module(name), clock_(clock), expected_(expected), pacer_(link), wake_(clock) {
  validate(link, "host output");
  results_.reserve(expected);
  arrivalCycles_.reserve(expected);
}

void HostSink::end_of_elaboration() {
  spawnMethod("evaluate", [this] { evaluate(); }, {&in->edge(), &wake_.event()});
}

void HostSink::evaluate() {
  const uint64_t now = clock_.now();
  if (handledCycle_ != now && now > 0 && in->transferredIn(now - 1)) {
    results_.push_back(in->transferred());
    arrivalCycles_.push_back(now - 1);
    allowedFrom_ = pacer_.nextAllowed(now - 1);
  }
  handledCycle_ = now;
  if (complete()) {
    in->setReady(false);
    return;
  }
  const bool ready = now >= allowedFrom_ && (!pacer_.random() || pacer_.drawActive());
  in->setReady(ready);
  if (pacer_.random())
    wake_.at(now + 1);  // a new draw every cycle
  else if (!ready)
    wake_.at(allowedFrom_);
}

}  // namespace rtu
