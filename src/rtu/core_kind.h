#pragma once
// The seam between the RTU and a kind of traversal core. The RTU's job manager timing, scheduler,
// result manager, reorder buffer, host links, recurrence and scene manager never look inside a
// job, and ask a result only what the kind answers (below); the shells (the cycle-accurate core,
// the loosely-timed core and top, the cache warmer, the untimed shell of rtu/golden_shell.h, the
// analytic run's tracer, the per-cycle RTL reference's core slots) are templates over a kind. A
// kind is a struct of types and static members, chosen once at the top (kinds/registry.h) so that
// nothing below branches on it and no virtual call lies on the per-cycle path. kinds/svo/svo_kind.h
// is the worked example; docs/architecture.md, "The core-kind seam", lists what a kind declares.
// What the shells rely on besides the types (docs/cycle-semantics.md, "Access width and multi-cycle
// states"):
//   kWordsPerRead        a power of two: a reading state reads that many words from memoryAddress()
//                        rounded down to a multiple of it (one access, within one line), and its
//                        behaviour's readWord calls stay within them;
//   stateCycles(b)       the cycles of b's current state, asked before it is stepped;
//   Behaviour::cost()    the job's states' own cycles (stateCycles each), blocked ones excluded;
//   Config               its own settings, with validate() (throws std::invalid_argument naming the
//                        setting); the RTU's configuration holds every registered kind's
//                        (RtuConfig::coreConfig<Kind>());
//   Setup                the job manager's set-up of a host record (JobSetUp below), made from
//                        (memory, JobManagerTiming, Config): setUp(const RayRecord&) and, for a
//                        kind with its own Record, setUp(const Record&); a record it has no
//                        overload for is refused (kinds/host_record.h); the job manager's and
//                        the cache warmer's (run/cache_warmer.h);
//   Record               the kind's own record, if any (naming itself by kName);
//   resultRecordBytes(config)  a result's record on the host output link.
// A kind with a pipelined ray/triangle unit (the triangle kinds) also declares, so that the shells
// can share one unit among a group of cores (RtuConfig::triangleSharedBy, HasTriangleUnit below):
//   issuesTriangleTest(b)  whether b's current state issues a test to the unit (its first cycle
//                          then waits for the unit's grant);
//   triangleInterval(config)   the unit's initiation interval: cycles from one issue to the next.
// What the kind-agnostic machinery asks of a Result (the payloads, the host sink and the runs carry
// it as a CoreKindResult, kinds/registry.h; kinds/core_result.h asks through these):
//   resultIdWord(r)      the id word the job's set-up gave it, carried back unchanged;
//   resultHit(r)         whether the job hit anything;
//   resultCost(r), setResultCost(r, cost)  its cost in cycles (Behaviour::cost()), and the scene
//                        manager's replacement of it by the sum over a ray's jobs;
//   resultBelowResolution(r)  flagged for reaching below the arithmetic's resolution (the run's
//                        below_resolution; false for a kind without such a limit);
//   countResult(r, counters)  its Counters counted from the result alone (the recurrence's runs,
//                        which have no behaviour), as count(behaviour, counters) counts them;
//   miss(idWord)         a miss carrying idWord at no cost (a scene's ray before any hit);
//   hitAhead(r)          a hit ahead of the ray's origin: what a scene counts as a hit;
//   nearer(a, b)         hit a strictly nearer than hit b (neither: as near; the scene manager
//                        then takes the lower instance);
//   hitDistance(r, config)  how far along the ray a hit lies, in the units of its direction, as
//                        the kind's set-up with its Config set the job up (early termination).

#include <cstdint>
#include <string>
#include <type_traits>
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

// Whether `Kind` has a ray/triangle unit (declares issuesTriangleTest).
template <class Kind, class = void>
struct HasTriangleUnit : std::false_type {};
template <class Kind>
struct HasTriangleUnit<Kind, std::void_t<decltype(&Kind::issuesTriangleTest)>> : std::true_type {};

// Whether `behaviour`'s current state issues a test to its unit; the unit's interval (1 without).
template <class Kind>
bool issuesTriangleTest(const typename Kind::Behaviour& behaviour) {
  if constexpr (HasTriangleUnit<Kind>::value)
    return Kind::issuesTriangleTest(behaviour);
  else
    return false;
}
template <class Kind>
uint32_t triangleIntervalOf(const typename Kind::Config& config) {
  if constexpr (HasTriangleUnit<Kind>::value)
    return Kind::triangleInterval(config);
  else
    return 1;
}

}  // namespace rtu
