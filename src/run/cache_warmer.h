#pragma once
// Functional warming (SMARTS, Wunderlich et al. 2003): the caches' contents brought up to date
// with rays that are not simulated, by setting them up as the job manager does (Kind::Setup) and
// tracing them untimed with a core kind's behaviour (rtu/core_kind.h), touching, for each access a
// traversal makes (Kind::kWordsPerRead words aligned to that count, so within one line), its line
// in an L1 and, when the L1 did not hold it, in the L2. Nothing is timed or counted. Which core
// runs a ray depends on timing the warmer does not model, so ray i warms the L1 of core i mod
// cores, as the cyclic scheduler hands out rays of equal cost.

#include <cstdint>
#include <type_traits>
#include <variant>
#include <vector>

#include "kinds/host_record.h"
#include "sim/memory/cache_contents.h"
#include "sim/memory/l1_cache_timing.h"
#include "sim/rtu_config.h"

namespace rtu {

template <class Kind>
class CacheWarmer {
 public:
  // `config.memory` must be cached.
  CacheWarmer(typename Kind::Memory memory, const RtuConfig& config)
      : memory_(memory),
        config_(config.coreConfig<Kind>()),
        cores_(config.cores),
        setup_(memory, config.jobManager, config_),
        core_(Kind::behaviour(config_)) {
    contents_.l1.assign(static_cast<size_t>(cores_), CacheArray(config.memory.l1));
    contents_.l2.assign(1, CacheArray(config.memory.l2));
  }

  // Traces records[next .. end) untimed, set up as the job manager sets them up, touching their
  // lines; `next` is where the last call ended. A record is a HostRecordOf variant (its kind's
  // overload, kinds/host_record.h) or a type the kind's Setup takes.
  template <class Record>
  void warmUpTo(const std::vector<Record>& records, uint64_t end) {
    for (; next_ < end; ++next_) {
      const int core = static_cast<int>(next_ % static_cast<uint64_t>(cores_));
      Kind::start(core_, setUp(records[next_]));
      while (core_.busy()) {
        if (core_.readsMemory()) touch(core, core_.memoryAddress());
        core_.step([this](uint32_t address) { return memory_.read(address); });
      }
      core_.finish();
    }
  }
  // Traces every record `frames` times, as that many frames before the run leave the caches (the
  // warm_frames setting); the next warmUpTo starts again from the first record.
  template <class Record>
  void warmFrames(const std::vector<Record>& records, int frames) {
    for (int frame = 0; frame < frames; ++frame) {
      next_ = 0;
      warmUpTo(records, records.size());
    }
    next_ = 0;
  }
  uint64_t next() const { return next_; }
  const CacheContents& contents() const { return contents_; }

 private:
  template <class Record>
  struct IsVariant : std::false_type {};
  template <class... Records>
  struct IsVariant<std::variant<Records...>> : std::true_type {};

  template <class Record>
  typename Kind::Job setUp(const Record& record) {
    if constexpr (IsVariant<Record>::value)
      return setUpHostRecord<Kind>(setup_, record).job;
    else
      return setup_.setUp(record).job;
  }

  // The access of the word at `wordAddress`: its first word's line.
  void touch(int core, uint32_t wordAddress) {
    const uint64_t byteAddress =
        L1CacheTiming::byteAddress(wordAddress & ~uint32_t{Kind::kWordsPerRead - 1});
    if (!contents_.l1[static_cast<size_t>(core)].touch(byteAddress))
      contents_.l2.front().touch(byteAddress);
  }

  typename Kind::Memory memory_;
  typename Kind::Config config_;
  int cores_;
  typename Kind::Setup setup_;
  typename Kind::Behaviour core_;
  CacheContents contents_;
  uint64_t next_ = 0;
};

}  // namespace rtu
