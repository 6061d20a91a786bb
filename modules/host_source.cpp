#include "host_source.h"

#include <algorithm>

namespace rtu {

HostSource::HostSource(sc_core::sc_module_name name, const CycleClock& clock,
                       std::vector<HostRecord> records, HostLinkConfig link)
    : sc_core::sc_module(name),
      clock_(clock),
      records_(std::move(records)),
      pacer_(link),
      wake_(clock) {
  validate(link, "host input");
}

void HostSource::end_of_elaboration() {
  spawnMethod("evaluate", [this] { evaluate(); }, {&out->edge(), &wake_.event()});
}

void HostSource::evaluate() {
  const uint64_t now = clock_.now();
  if (offering_ && now > 0 && out->transferredIn(now - 1)) {
    ++next_;
    allowedFrom_ = pacer_.nextAllowed(now - 1);
    offering_ = false;
    out->withdraw();
  }
  if (next_ == records_.size()) return;  // nothing left: no more activations
  if (!offering_ && now >= allowedFrom_ && (!pacer_.random() || pacer_.drawActive())) {
    out->offer(HostJob{next_, records_[next_]});
    offering_ = true;
  }
  if (!offering_) wake_.at(std::max(now + 1, allowedFrom_));
}

}  // namespace rtu
