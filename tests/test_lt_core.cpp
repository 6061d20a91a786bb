// The loosely-timed core and the cache warmer over a kind other than SVO (toy_kind.h: two-word
// accesses, states of three cycles): the cycles and accesses of a job against a target of known
// latency, derived by hand from docs/cycle-semantics.md ("Access width and multi-cycle states");
// payloads the targets refuse, and the core's report of them; the lines the warmer touches.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include <tlm_utils/simple_target_socket.h>

#include "run/cache_warmer.h"
#include "sim/kernel/sc_kernel.h"
#include "sim/lt/lt_core.h"
#include "sim/lt/lt_dram.h"
#include "sim/lt/lt_l1_cache.h"
#include "sim/lt/lt_l2_cache.h"
#include "sim/lt/lt_word_read.h"
#include "toy_kind.h"

namespace rtu {
namespace {

// Word i of the image is 100 + i.
std::vector<uint32_t> image() {
  std::vector<uint32_t> words(512);
  for (uint32_t i = 0; i < words.size(); ++i) words[i] = 100 + i;
  return words;
}

// A target whose data is there `latency` cycles after the request; it records each access.
class LatencyTarget : public sc_core::sc_module {
 public:
  struct Access {
    uint64_t byteAddress, bytes, cycle;
    bool operator==(const Access& o) const {
      return byteAddress == o.byteAddress && bytes == o.bytes && cycle == o.cycle;
    }
  };
  tlm_utils::simple_target_socket<LatencyTarget> socket;
  std::vector<Access> accesses;

  LatencyTarget(sc_core::sc_module_name name, WordMemory words, const LtTime& time,
                uint64_t latency)
      : sc_module(name), socket("socket"), words_(words), time_(time), latency_(latency) {
    socket.register_b_transport(this, &LatencyTarget::b_transport);
  }

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
    const uint64_t cycle = time_.cycleAt(delay);
    accesses.push_back({trans.get_address(), trans.get_data_length(), cycle});
    if (acceptWordRead(trans, 64)) serveWordRead(words_, trans);
    delay = time_.delayTo(cycle + latency_);
  }

  WordMemory words_;
  LtTime time_;
  uint64_t latency_;
};

// Elaborates the modules made since freshKernel(), so that their sockets are bound; the targets
// are then called directly, nothing is simulated.
void elaborate() {
  sc_core::sc_report_handler::set_actions(sc_core::SC_ID_NO_SC_START_ACTIVITY_,
                                          sc_core::SC_DO_NOTHING);
  simulateFor(sc_core::SC_ZERO_TIME);
}

struct ToyRun {
  LtTraversal timing;
  ToyResult result;
  std::vector<LatencyTarget::Access> accesses;
};

// The toy job from base word 8, its first state in cycle 10, through a target of `latency`.
ToyRun runToy(uint64_t latency) {
  freshKernel();
  const std::vector<uint32_t> words = image();
  const LtTime time(CycleClock::atMegahertz(100));
  ToyBehaviour behaviour;
  LtCore<ToyKind> core("core", behaviour, time);
  LatencyTarget target("target", WordMemory(words), time, latency);
  core.memory.bind(target.socket);
  elaborate();
  ToyRun run;
  run.timing = core.traverse(7, 8, 10, run.result);
  run.accesses = target.accesses;
  return run;
}

using Accesses = std::vector<LatencyTarget::Access>;

}  // namespace

TEST_CASE("LT core: two-word accesses and three-cycle states, by hand", "[lt][lt_core]") {
  // The walk from base 8: S0 1 cycle; S1 1 cycle, reads words 8-9; S2 3 cycles, reads word 13,
  // so words 12-13; S3 3 cycles; S4 1 cycle, reads words 10-11. Own cycles 1+1+3+3+1 = 9. Every
  // access is 8 bytes at the pair's first word. Sum (108+109) + (113+112) + (110+111) = 663.
  const ToyResult expected{7, 663, 9};

  SECTION("latency 4: every read blocks") {
    // S0 in 10. S1 reads in 11, data in 15: ends in 15 (4 blocked). S2 from 16, reads in 16,
    // data in 20, its own cycles end in 18: ends in 20 (2 blocked). S3 in 21-23. S4 reads in 24,
    // data in 28 (4 blocked). OUT in 29: 19 cycles, 10 blocked.
    const ToyRun run = runToy(4);
    CHECK(run.result == expected);
    CHECK(run.timing.cycles == 19);
    CHECK(run.timing.blocked == 10);
    CHECK(run.accesses == Accesses{{32, 8, 11}, {48, 8, 16}, {40, 8, 24}});
  }
  SECTION("latency 1: a three-cycle state hides its read") {
    // S0 in 10. S1 reads in 11, data in 12 (1 blocked). S2 in 13-15, reads in 13, data in 14:
    // within its own cycles. S3 in 16-18. S4 reads in 19, data in 20 (1 blocked). OUT in 21:
    // 11 cycles, 2 blocked.
    const ToyRun run = runToy(1);
    CHECK(run.result == expected);
    CHECK(run.timing.cycles == 11);
    CHECK(run.timing.blocked == 2);
    CHECK(run.accesses == Accesses{{32, 8, 11}, {48, 8, 13}, {40, 8, 19}});
  }
  SECTION("latency 0: the states' own cycles") {
    // S0 10, S1 11, S2 12-14, S3 15-17, S4 18, OUT in 19.
    const ToyRun run = runToy(0);
    CHECK(run.result == expected);
    CHECK(run.timing.cycles == 9);
    CHECK(run.timing.blocked == 0);
    CHECK(run.accesses == Accesses{{32, 8, 11}, {48, 8, 12}, {40, 8, 18}});
  }
}

TEST_CASE("LT targets: reads of whole words within a line, others refused", "[lt][lt_core]") {
  freshKernel();
  const std::vector<uint32_t> words = image();
  const LtTime time(CycleClock::atMegahertz(100));
  MemoryConfig memory;
  memory.ideal = false;
  memory.l1.lineBytes = 16;
  LtL1Cache l1("l1", memory.l1, 8, WordMemory(words), time);  // the toy core's 8-byte access
  LtL1Cache narrowL1("narrow_l1", memory.l1, 4, WordMemory(words), time);
  LtL2Cache l2("l2", memory, time);
  LtDram dram("dram", memory.dram, memory.l2.lineBytes, time);
  l1.next.bind(l2.socket);
  narrowL1.next.bind(l2.socket);
  l2.dram.bind(dram.socket);
  ToyBehaviour behaviour;
  LtCore<ToyKind> core("core", behaviour, time);
  LtCore<ToyKind> l1Core("l1_core", behaviour, time);  // binds the L1's socket
  core.memory.bind(narrowL1.socket);
  l1Core.memory.bind(l1.socket);
  elaborate();

  uint32_t data[4] = {};
  tlm::tlm_generic_payload read;
  read.set_read();
  read.set_data_ptr(reinterpret_cast<unsigned char*>(data));
  const auto status = [&](auto& target, uint64_t address, uint32_t bytes) {
    read.set_address(address);
    read.set_data_length(bytes);
    read.set_streaming_width(bytes);
    read.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    target.b_transport(read, delay);
    return read.get_response_status();
  };
  SECTION("the L2 serves words within its 64-byte line") {
    CHECK(status(l2, 48, 16) == tlm::TLM_OK_RESPONSE);           // bytes 48-63
    CHECK(status(l2, 56, 16) == tlm::TLM_BURST_ERROR_RESPONSE);  // 56-71 crosses into line 64
    CHECK(status(l2, 48, 6) == tlm::TLM_BURST_ERROR_RESPONSE);   // part of a word
    CHECK(status(l2, 50, 8) == tlm::TLM_BURST_ERROR_RESPONSE);   // not word-aligned
    CHECK(status(l2, 48, 0) == tlm::TLM_BURST_ERROR_RESPONSE);   // empty
    read.set_write();
    CHECK(status(l2, 48, 4) == tlm::TLM_COMMAND_ERROR_RESPONSE);
  }
  SECTION("an L1 serves its core's access alone") {
    CHECK(status(l1, 40, 8) == tlm::TLM_OK_RESPONSE);  // words 10-11
    CHECK(data[0] == 110);
    CHECK(data[1] == 111);
    CHECK(status(l1, 36, 8) == tlm::TLM_BURST_ERROR_RESPONSE);   // not aligned to the access
    CHECK(status(l1, 40, 4) == tlm::TLM_BURST_ERROR_RESPONSE);   // part of the access
    CHECK(status(l1, 32, 16) == tlm::TLM_BURST_ERROR_RESPONSE);  // two accesses
    read.set_write();
    CHECK(status(l1, 40, 8) == tlm::TLM_COMMAND_ERROR_RESPONSE);
    CHECK(l1.statistics().accesses == 1);  // the refused ones were not timed
  }
  SECTION("an L1 refuses a wider access than its core's, and the core says so") {
    ToyResult result;
    // S1's access: words 8-9, bytes 32-39, to an L1 made for 4-byte accesses.
    CHECK_THROWS_WITH(core.traverse(0, 8, 10, result),
                      Catch::Contains("core: memory read of 8 bytes at byte address 32 failed: "
                                      "TLM_BURST_ERROR_RESPONSE"));
    CHECK(narrowL1.statistics().accesses == 0);  // refused before it was timed
  }
}

TEST_CASE("An L1 is made only for accesses within its line", "[lt][lt_core]") {
  freshKernel();
  const std::vector<uint32_t> words = image();
  const LtTime time(CycleClock::atMegahertz(100));
  CacheConfig l1;
  l1.lineBytes = 4;
  CHECK_THROWS_WITH(LtL1Cache("l1", l1, 8, WordMemory(words), time),
                    "an L1 of 4-byte lines cannot serve accesses of 8 bytes");
  CHECK_THROWS_AS(LtL1Cache("l1", l1, 2, WordMemory(words), time), std::invalid_argument);
  l1.lineBytes = 16;
  CHECK_THROWS_AS(LtL1Cache("l1", l1, 12, WordMemory(words), time), std::invalid_argument);
}

TEST_CASE("Cache warmer: one touch per two-word access, in its core's L1", "[lt_core]") {
  const std::vector<uint32_t> words = image();
  RtuConfig config;
  config.cores = 2;
  config.memory.ideal = false;
  config.memory.l1.lineBytes = 16;  // lines of 4 words
  config.memory.l2.lineBytes = 64;
  CacheWarmer<ToyKind> warmer(WordMemory(words), config);
  // Job 0 (base 8) on core 0 reads words 8-9, 12-13 and 10-11: bytes 32, 48 and 40, so the L1
  // lines at 32 and 48 (40 lies in 32's); the L2 line at 0 holds both. Job 1 (base 64) on core 1
  // reads words 64-65, 68-69, 66-67: the L1 lines at 256 and 272, the L2 line at 256.
  warmer.warmUpTo(std::vector<ToyKind::Record>{8, 64}, 2);
  CHECK(warmer.next() == 2);
  const CacheContents& caches = warmer.contents();
  CHECK(caches.l1[0].contains(32));
  CHECK(caches.l1[0].contains(48));
  CHECK_FALSE(caches.l1[0].contains(16));
  CHECK_FALSE(caches.l1[0].contains(64));
  CHECK_FALSE(caches.l1[0].contains(256));
  CHECK(caches.l1[1].contains(256));
  CHECK(caches.l1[1].contains(272));
  CHECK_FALSE(caches.l1[1].contains(288));
  CHECK_FALSE(caches.l1[1].contains(32));
  CHECK(caches.l2[0].contains(0));
  CHECK(caches.l2[0].contains(256));
  CHECK_FALSE(caches.l2[0].contains(64));
  CHECK_FALSE(caches.l2[0].contains(320));
}

}  // namespace rtu
