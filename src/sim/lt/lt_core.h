#pragma once
// A core of the loosely-timed model for any core kind (rtu/core_kind.h): a TLM-2.0 initiator.
// traverse() steps the kind's behaviour through a whole job at once, ahead of simulated time, with
// the cycle accounting of the cycle-accurate core (sim/ca/timed_core.h; docs/cycle-semantics.md,
// "Access width and multi-cycle states"): the first state in the cycle after dispatch; a state of
// k = Kind::stateCycles cycles that starts in c issues its read in c and ends in
// max(c + k - 1, the cycle its data is there); the next state starts in the cycle after. The
// cycles beyond the states' own were blocked.
//
// A reading state's access is one b_transport on `memory` of Kind::kWordsPerRead words aligned to
// that count (so within one line), the delay annotated to the state's first cycle and returned with
// the cycle the data is there; the state's reads are served from the access's buffer. With DMI
// granted (the ideal ROM) it reads the image directly and every word is there in its cycle. The
// caller (lt_top.h) keeps the quantum.
//
// The behaviour is the caller's and may serve several cores: a job runs from start() to OUT within
// one traverse() call, so no core's traversal state outlives its job. One behaviour for all the
// cores stays in the host's caches; one per core (5.8 KB each for SVO, its stack) did not, and
// each dispatch to another core missed them.

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "rtu/core_kind.h"
#include "rtu/word_memory.h"
#include "sim/lt/lt_time.h"
#include "sim/memory/resource_booking.h"

namespace rtu {

// A job's time on its core: the cycles from its first state to OUT, how many of them were
// blocked on memory, and how many its tests waited for a shared triangle unit.
struct LtTraversal {
  uint64_t cycles = 0;
  uint32_t blocked = 0;
  uint64_t stalled = 0;
};

// A triangle unit shared by a group of cores (core.triangle.shared_by): its issues booked one
// interval each, in any order, since one traversal runs after another (resource_booking.h).
// Approximate: a test takes the first free slot at or after its state's first cycle, as if the
// traversals booked in cycle order, not the cycle-accurate model's round-robin.
struct LtTriangleUnit {
  ResourceBooking issues{RequestOrder::Any};
  uint32_t interval = 1;
};

template <class Kind>
class LtCore : public sc_core::sc_module {
 public:
  using Behaviour = typename Kind::Behaviour;
  static constexpr uint32_t kWords = Kind::kWordsPerRead;
  static_assert(kWords > 0 && (kWords & (kWords - 1)) == 0,
                "an access is a power of two words, aligned to its size");

  tlm_utils::simple_initiator_socket<LtCore> memory;

  // `behaviour` must outlive this and be idle between traverse() calls; so must `unit`, its shared
  // triangle unit (null: a unit of its own, which never keeps a test waiting).
  LtCore(sc_core::sc_module_name name, Behaviour& behaviour, const LtTime& time,
         LtTriangleUnit* unit = nullptr)
      : sc_core::sc_module(name),
        memory("memory"),
        time_(time),
        period_(time.period()),
        core_(behaviour),
        unit_(unit) {
    read_.set_read();
    read_.set_data_ptr(reinterpret_cast<unsigned char*>(data_.data()));
    read_.set_data_length(sizeof data_);
    read_.set_streaming_width(sizeof data_);
  }

  // Runs `job` from its first state in `initCycle` to OUT into `result` (written in place: a
  // returned struct was copied through a stall on its just-written fields).
  LtTraversal traverse(uint32_t idWord, const typename Kind::Job& job, uint64_t initCycle,
                       typename Kind::Result& result) {
    if (!dmiAsked_) acquireDmi();
    Kind::start(core_, job);
    const LtTraversal timing = dmi_ && !unit_ ? stepDirect() : stepThroughSocket(initCycle);
    Kind::writeResult(idWord, core_, result);
    core_.finish();
    return timing;
  }

 private:
  // Asked once, at the first job: the targets are bound by then.
  void acquireDmi() {
    dmiAsked_ = true;
    tlm::tlm_dmi dmi;
    read_.set_address(0);
    if (!memory->get_direct_mem_ptr(read_, dmi) || !dmi.is_read_allowed()) return;
    dmi_ = true;
    direct_ = WordMemory(reinterpret_cast<const uint32_t*>(dmi.get_dmi_ptr()),
                         static_cast<size_t>((dmi.get_end_address() + 1) / 4));
  }

  // Every word there in its state's first cycle: the job takes its states' own cycles.
  LtTraversal stepDirect() {
    while (core_.busy()) core_.step([this](uint32_t address) { return direct_.read(address); });
    return {core_.cost(), 0};
  }

  // The state's first cycle is kept as a delay after simulated time: a cycle is an addition, and
  // an access returns the delay to the cycle its data is there. For one-cycle states (k a
  // constant 1, as SVO's) the state's end is that cycle: a target does not answer before the
  // request.
  LtTraversal stepThroughSocket(uint64_t initCycle) {
    Behaviour& core = core_;  // in a register: the member is reloaded after a read
    sc_core::sc_time delay = time_.delayTo(initCycle);
    uint64_t stalled = 0;
    while (core.busy()) {
      if (unit_ && issuesTriangleTest<Kind>(core)) delay = awaitUnit(delay, stalled);
      const uint32_t cycles = Kind::stateCycles(core);
      const sc_core::sc_time first = delay;
      stepState(core, delay);
      if (cycles > 1) delay = std::max(delay, first + time_.cycles(cycles - 1));
      delay += period_;
    }
    const uint64_t total = time_.cycleAt(delay) - initCycle;
    return {total, static_cast<uint32_t>(total - core.cost() - stalled), stalled};
  }

  // The test of the state beginning at `delay` issues in the unit's first free slot from then:
  // the delay to it, the wait added to `stalled`.
  sc_core::sc_time awaitUnit(const sc_core::sc_time& delay, uint64_t& stalled) {
    const uint64_t asked = time_.cycleAt(delay);
    const uint64_t granted = unit_->issues.book(asked, unit_->interval);
    stalled += granted - asked;
    return time_.delayTo(granted);
  }

  // Steps the current state. Its first read issues the state's access at `delay`, its first cycle
  // (`delay` becomes the delay to the cycle the data is there); every read of the state is served
  // from the access. Forced inline with the behaviour's step: it runs once per simulated state.
  [[gnu::always_inline]] inline void stepState(Behaviour& core, sc_core::sc_time& delay) {
    bool issued = false;
    uint32_t block = 0;  // the state's access, by its first word
    core.stepInline([this, &delay, &issued, &block](uint32_t address) {
      const uint32_t first = address & ~(kWords - 1);
      if (kWords == 1 || !issued) {
        issued = true;
        block = first;
        access(first, delay);
      } else if (first != block) {
        readOutsideAccess(address);
      }
      return data_[address & (kWords - 1)];
    });
  }

  // Reads the kWords words from `first` at `delay` after simulated time into the buffer; `delay`
  // becomes the delay to the cycle they are there.
  void access(uint32_t first, sc_core::sc_time& delay) {
    read_.set_address(uint64_t{first} * 4);
    read_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    memory->b_transport(read_, delay);
    if (read_.is_response_error()) failRead();
  }

  // Out of the stepping loop's line: report what failed.
  [[noreturn, gnu::noinline]] void failRead() const {
    throw std::runtime_error(std::string(name()) + ": memory read of " +
                             std::to_string(read_.get_data_length()) + " bytes at byte address " +
                             std::to_string(read_.get_address()) +
                             " failed: " + read_.get_response_string() + explain(read_));
  }
  static std::string explain(const tlm::tlm_generic_payload& read) {
    return read.get_response_status() == tlm::TLM_BURST_ERROR_RESPONSE
               ? " (a target serves whole words within one line; is its line shorter than an "
                 "access?)"
               : "";
  }
  [[noreturn, gnu::noinline]] void readOutsideAccess(uint32_t address) const {
    throw std::logic_error(std::string(name()) + ": the state read word " +
                           std::to_string(address) + " outside its access of " +
                           std::to_string(kWords) + " words from word " +
                           std::to_string(read_.get_address() / 4));
  }

  LtTime time_;
  sc_core::sc_time period_;
  Behaviour& core_;
  LtTriangleUnit* unit_;
  tlm::tlm_generic_payload read_;
  std::array<uint32_t, kWords> data_{};  // the access's words
  WordMemory direct_;                    // the image through DMI, when granted
  bool dmiAsked_ = false, dmi_ = false;
};

}  // namespace rtu
