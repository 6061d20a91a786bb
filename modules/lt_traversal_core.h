#pragma once
// A traversal core of the loosely-timed model: a TLM-2.0 initiator with temporal decoupling
// (tlm_utils::tlm_quantumkeeper, after the Accellera lt_td_initiator example). Its thread asks
// for a job, steps the shared state machine (golden/traversal_core.h) through the whole traversal
// ahead of simulated time, and hands the result over; it yields to the kernel only when its local
// time passes the global quantum, after a ray. The cycle accounting is the cycle-accurate core's
// (svo_traversal_core.h): INIT in dispatch + 1, one cycle per state, and a read whose word is
// there in d > c costs BLOCKED in c + 1 .. d.
//
// Each word it reads is a b_transport on `memory`, the delay annotated to the state's cycle and
// returned with the cycle the word is there; with DMI granted (the ideal ROM) it reads the
// image directly and every word is there in its cycle.

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "fixed_point.h"
#include "lt_time.h"
#include "lt_transactions.h"
#include "traversal_core.h"

namespace rtu {

class LtTraversalCore : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<LtTraversalCore> memory;
  sc_core::sc_port<LtJobSourceIf> jobs;
  sc_core::sc_port<LtResultSinkIf> results;

  LtTraversalCore(sc_core::sc_module_name name, int index, FixedFormat format, int stackFrames,
                  const LtTime& time);

 private:
  void run();
  void acquireDmi();
  // Steps the job dispatched in `dispatch` to OUT; returns the OUT cycle, blocked cycles counted.
  uint64_t traverse(uint64_t dispatch, uint32_t& blocked);
  // The word at `address`, read in `cycle`; `cycle` becomes the cycle it is there.
  uint32_t readWord(uint32_t address, uint64_t& cycle);
  void keepQuantum(uint64_t cycle);

  int index_;
  LtTime time_;
  TraversalCore<FixedArith> core_;
  tlm_utils::tlm_quantumkeeper quantum_;
  tlm::tlm_generic_payload read_;
  uint32_t word_ = 0;  // the read's data
  SvoMemory direct_;   // the image through DMI, when granted
  bool dmi_ = false;
};

}  // namespace rtu
