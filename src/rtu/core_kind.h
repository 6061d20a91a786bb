#pragma once
// The seam between the RTU and a kind of traversal core. The RTU's job manager timing, scheduler,
// result manager, reorder buffer, host links, recurrence and scene manager never look inside a
// job; the shells (the cycle-accurate core, the loosely-timed core and top, the cache warmer, the
// untimed shell of rtu/golden_shell.h, the analytic run's tracer, the per-cycle RTL reference's
// core slots) are templates over a kind. A kind is a struct of types and static members, chosen
// once at the top (kinds/registry.h) so that nothing below branches on it and no virtual call
// lies on the per-cycle path. kinds/svo/svo_kind.h is the worked example; docs/architecture.md,
// "The core-kind seam", lists what a kind declares. What the shells rely on besides the types
// (docs/cycle-semantics.md, "Access width and multi-cycle states"):
//   kWordsPerRead        a power of two: a reading state reads that many words from memoryAddress()
//                        rounded down to a multiple of it (one access, within one line), and its
//                        behaviour's readWord calls stay within them;
//   stateCycles(b)       the cycles of b's current state, asked before it is stepped;
//   Behaviour::cost()    the job's states' own cycles (stateCycles each), blocked ones excluded;
//   Setup                the job manager's set-up of a host record (JobSetUp below);
//   setUp(record, config) a t-value record's set-up from the kind's Config (the cache warmer's).

#include <cstdint>
#include <string>
#include <vector>

namespace rtu {

// How a kind's states appear in traces and timelines: a name per trace code, the code's width,
// and which codes are idle (ready for a job), out (result offered) and blocked (waiting for a
// word). A ray's timeline slice runs from the cycle its core leaves idle to the cycle its core is
// idle again.
struct StateVocabulary {
  std::vector<std::string> names;  // by code
  int bits = 0;
  uint64_t idle = 0, out = 0, blocked = 0;
};

// What a kind's job set-up (Kind::Setup) makes of a host record, as the job manager computes it:
// the core's job, the id word its result carries back, the cycles from acceptance to the
// pipeline's output (stalls aside) and the cycles after acceptance in which no record is accepted
// (a model header's fetch).
template <class Job>
struct JobSetUp {
  Job job;
  uint32_t idWord = 0;
  uint64_t latency = 0;
  uint64_t headerFetch = 0;
};

}  // namespace rtu
