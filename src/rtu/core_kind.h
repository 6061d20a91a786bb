#pragma once
// The seam between the RTU and a kind of traversal core. The RTU's job manager timing, scheduler,
// result manager, reorder buffer, host links, recurrence and scene manager never look inside a
// job; the shells (the cycle-accurate core, the untimed shell of rtu/golden_shell.h, the analytic
// run's tracer, the per-cycle RTL reference's core slots) are templates over a kind, the
// loosely-timed core and the cache warmer to follow. A kind is a struct of types and static
// members, chosen once at the top (kinds/registry.h) so that nothing below branches on it and no
// virtual call lies on the per-cycle path. kinds/svo/svo_kind.h is the worked example;
// docs/architecture.md, "The core-kind seam", lists what a kind declares.

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
