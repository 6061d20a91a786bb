#pragma once
// A traversal core of the loosely-timed model: a TLM-2.0 initiator. traverse() steps the shared
// state machine (src/kinds/svo/traversal_core.h) through a whole job at once, ahead of simulated
// time, with the cycle accounting of the cycle-accurate core (sim/ca/timed_core.h): INIT in the
// cycle after dispatch, one cycle per state, and a read issued in c whose word is there in d > c
// costs BLOCKED in c + 1 .. d.
//
// Each word it reads is a b_transport on `memory`, the delay annotated to the state's cycle and
// returned with the cycle the word is there; with DMI granted (the ideal ROM) it reads the image
// directly and every word is there in its cycle. The caller (lt_top.h) keeps the quantum.
//
// The state machine is the caller's and may serve several cores: a job runs from start() to OUT
// within one traverse() call, so no core's traversal state outlives its job. One state machine
// for all the cores stays in the host's caches; one per core (5.8 KB each, its stack) did not,
// and each dispatch to another core missed them.

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "kinds/svo/fixed_point.h"
#include "kinds/svo/traversal_core.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/lt/lt_time.h"

namespace rtu {

class LtTraversalCore : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<LtTraversalCore> memory;

  // `core` must outlive this and be idle between traverse() calls.
  LtTraversalCore(sc_core::sc_module_name name, TraversalCore<FixedArith>& core,
                  const LtTime& time);

  // Runs `job` from INIT in `initCycle` to OUT into `result` (written in place: a returned struct
  // was copied through a stall on its just-written fields); returns its blocked cycles.
  uint32_t traverse(const CoreJob& job, uint64_t initCycle, TraversalResult& result);

 private:
  void acquireDmi();
  // Steps the started job to its end through `memory`; returns its blocked cycles.
  uint32_t stepThroughSocket(uint64_t initCycle);
  // The word at `address`, read at `delay` after simulated time; `delay` becomes the delay to
  // the cycle it is there.
  uint32_t readWord(uint32_t address, sc_core::sc_time& delay);
  [[noreturn]] void failRead() const;  // out of the read's line: reports the failed read

  LtTime time_;
  sc_core::sc_time period_;
  TraversalCore<FixedArith>& core_;
  tlm::tlm_generic_payload read_;
  uint32_t word_ = 0;  // the read's data
  WordMemory direct_;  // the image through DMI, when granted
  bool dmiAsked_ = false, dmi_ = false;
};

}  // namespace rtu
