#pragma once
// The job manager's timing, whichever kind its cores are (thesis 6.2.1, appendix C.2): a record
// passes `stages` registers (the RTL's P_STAGES); a world-space ray record `rayStages` more (its
// transform into the model's space and the kind's set-up beyond it; the thesis leaves them as
// placeholders, so their latency is configuration), and the first ray against a model waits
// `headerFetchCycles` for the model's header, in which no record is accepted. What a record
// becomes is the kind's (Kind::Setup, rtu/core_kind.h); the cycle-accurate job manager, the
// recurrence and the RTL reference take only this.

namespace rtu {

struct JobManagerTiming {
  int stages = 6;  // P_STAGES
  int rayStages = 6;
  int headerFetchCycles = 16;  // one word per cycle
};

}  // namespace rtu
