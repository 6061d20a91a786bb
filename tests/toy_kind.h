#pragma once
// A toy core kind for the tests of the kind-generic shells (rtu/core_kind.h): what the
// loosely-timed core and the cache warmer need of a kind, with an access of two words and states
// of several cycles, which the SVO kind (one word, one cycle) does not exercise. Its behaviour
// walks one fixed sequence of states from a job's base word address and sums the words it reads.

#include <array>
#include <cstdint>
#include <stdexcept>

#include "rtu/core_kind.h"
#include "rtu/word_memory.h"
#include "sim/rtu_config.h"

namespace rtu {

struct ToyResult {
  uint32_t idWord = 0;
  uint32_t sum = 0;   // of every word read
  uint32_t cost = 0;  // the states' own cycles
  bool operator==(const ToyResult& other) const {
    return idWord == other.idWord && sum == other.sum && cost == other.cost;
  }
};

class ToyBehaviour {
 public:
  // One state of the walk: its cycles and the word it reads, as an offset from the job's base
  // (kNoRead: none). A reading state reads its word and the other word of its aligned pair, in
  // that order.
  struct Step {
    uint32_t cycles;
    int offset;
  };
  static constexpr int kNoRead = -1;
  static constexpr std::array<Step, 5> kWalk{{{1, kNoRead}, {1, 0}, {3, 5}, {3, kNoRead}, {1, 2}}};
  static constexpr int kOut = static_cast<int>(kWalk.size()), kIdle = kOut + 1;

  void start(uint32_t base) {
    base_ = base;
    state_ = 0;
    sum_ = 0;
    cost_ = 0;
  }
  int state() const { return state_; }
  bool busy() const { return state_ < kOut; }
  bool readsMemory() const { return kWalk[static_cast<size_t>(state_)].offset != kNoRead; }
  uint32_t memoryAddress() const {
    return base_ + static_cast<uint32_t>(kWalk[static_cast<size_t>(state_)].offset);
  }
  uint32_t stateCycles() const { return kWalk[static_cast<size_t>(state_)].cycles; }

  template <class ReadWord>
  void stepInline(ReadWord&& readWord) {
    if (!busy()) throw std::logic_error("toy behaviour stepped while not busy");
    if (readsMemory()) sum_ += readWord(memoryAddress()) + readWord(memoryAddress() ^ 1);
    cost_ += stateCycles();
    ++state_;
  }
  template <class ReadWord>
  void step(ReadWord&& readWord) {
    stepInline(readWord);
  }
  void finish() { state_ = kIdle; }
  uint32_t cost() const { return cost_; }
  uint32_t sum() const { return sum_; }
  int stackSize() const { return 0; }

 private:
  uint32_t base_ = 0, sum_ = 0, cost_ = 0;
  int state_ = kIdle;
};

struct ToyKind {
  static constexpr const char* kName = "toy";
  using Record = uint32_t;  // the base word address
  using Job = uint32_t;
  using Result = ToyResult;
  using Behaviour = ToyBehaviour;
  using Memory = WordMemory;
  struct Config {
    void validate() const {}
  };

  static constexpr int kWordsPerRead = 2;
  static uint32_t stateCycles(const Behaviour& core) { return core.stateCycles(); }
  static constexpr uint64_t kFirstReadAfterDispatch = 2;

  static Behaviour behaviour(const Config&) { return {}; }
  // The job manager's set-up of a record: the base address as it is (the cache warmer's).
  class Setup {
   public:
    Setup(WordMemory, const JobManagerTiming&, const Config&) {}
    JobSetUp<Job> setUp(const Record& record) const { return {record, record, 0, 0}; }
  };
  static void start(Behaviour& core, const Job& job) { core.start(job); }
  static void writeResult(uint32_t idWord, const Behaviour& core, Result& result) {
    result = ToyResult{idWord, core.sum(), core.cost()};
  }

  // What the kind-agnostic machinery asks of a result (kinds/core_result.h): a toy job hits when
  // it read a word other than zero, at the distance of the sum it read; it counts odd sums.
  struct Counters {
    uint64_t oddSums = 0;
  };
  static uint32_t resultIdWord(const Result& result) { return result.idWord; }
  static bool resultHit(const Result& result) { return result.sum != 0; }
  static uint32_t resultCost(const Result& result) { return result.cost; }
  static void setResultCost(Result& result, uint32_t cost) { result.cost = cost; }
  static bool resultBelowResolution(const Result& result) { return result.sum == 1; }
  static void countResult(const Result& result, Counters& counters) {
    counters.oddSums += result.sum % 2;
  }
  static Result miss(uint32_t idWord) { return ToyResult{idWord, 0, 0}; }
  static bool hitAhead(const Result& result) { return resultHit(result); }
  static bool nearer(const Result& a, const Result& b) { return a.sum < b.sum; }
  static double hitDistance(const Result& result, const Config&) { return result.sum; }
};

}  // namespace rtu
