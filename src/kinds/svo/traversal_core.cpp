#include "kinds/svo/traversal_core.h"

namespace rtu {

const char* toString(CoreState state) {
  switch (state) {
    case CoreState::Idle: return "IDLE";
    case CoreState::Init: return "INIT";
    case CoreState::Eval: return "EVAL";
    case CoreState::Next: return "NEXT";
    case CoreState::Push: return "PUSH";
    case CoreState::Pop: return "POP";
    case CoreState::Out: return "OUT";
  }
  return "?";
}

}  // namespace rtu
