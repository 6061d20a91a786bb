#pragma once
// The host's side of a run as streams (docs/robustness.md, "Memory"): the records a run reads
// (a vector the caller holds, or records made one at a time when the run asks for them, as a
// frame's from its camera) and the results it hands out as they leave (taken, not kept), so that
// a frame's run holds no record or result per ray of the whole frame.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kinds/registry.h"

namespace rtu {

// A run's records by index. A run asks for them in increasing order, each once; what reads them
// more than once (warm frames, a trace's dry runs) takes them all() into a vector first.
class RecordSource {
 public:
  using Make = std::function<HostRecord(uint64_t index)>;

  // The caller's records, which must outlive the source (implicit: a run that took a vector of
  // records takes one still).
  RecordSource(const std::vector<HostRecord>& records)  // NOLINT(google-explicit-constructor)
      : records_(&records), size_(records.size()) {}
  // `size` records, index i made by make(i) when asked; all of the alternative of `sample`
  // (record 0 made beforehand), which checkCoreTakes checks for all.
  RecordSource(uint64_t size, Make make, HostRecord sample)
      : size_(size), make_(std::move(make)), sample_(std::move(sample)) {}

  uint64_t size() const { return size_; }
  HostRecord operator[](uint64_t index) const {
    return records_ ? (*records_)[index] : make_(index);
  }
  // Every record in one vector (made records made now), for what reads them more than once.
  std::vector<HostRecord> all() const {
    if (records_) return *records_;
    std::vector<HostRecord> made;
    made.reserve(size_);
    for (uint64_t i = 0; i < size_; ++i) made.push_back(make_(i));
    return made;
  }
  // The caller's vector, or null for records made when asked.
  const std::vector<HostRecord>* vector() const { return records_; }
  // A made source's record 0, made beforehand (null for a vector's).
  const HostRecord* sample() const { return sample_ ? &*sample_ : nullptr; }

 private:
  const std::vector<HostRecord>* records_ = nullptr;
  uint64_t size_ = 0;
  Make make_;
  std::optional<HostRecord> sample_;
};

// Takes each result of the run as the host receives it (job: the index of its record), in the
// order of arrival; a run that hands its results to a taker keeps none of them.
using ResultTaker = std::function<void(uint64_t job, const CoreKindResult& result)>;

// The rays a streaming run's host holds at once: made by its record source and not yet taken
// as results. A run holds what its buffers hold, so the most stays bounded by the RTU, not the
// frame (tests/test_host_stream.cpp).
struct RaysHeld {
  uint64_t made = 0, taken = 0, most = 0;

  void madeOne() {
    ++made;
    if (made - taken > most) most = made - taken;
  }
  void tookOne() { ++taken; }
};

// checkCoreTakes (registry.h) for a source: a made source's records share one alternative.
inline void checkCoreTakes(const std::string& core, const RecordSource& records) {
  if (const std::vector<HostRecord>* held = records.vector()) return checkCoreTakes(core, *held);
  if (records.size() > 0) checkCoreTakes(core, std::vector<HostRecord>{*records.sample()});
}

}  // namespace rtu
