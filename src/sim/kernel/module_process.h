#pragma once
// The SystemC processes of the few modules that must wait for simulated time (the memory's shared
// requests, the host source's look-ahead, drains in cycle order; decision_pump.h): method
// processes statically sensitive to a wake-up the module sets for a cycle of its choosing.
// Dynamic sensitivity (next_trigger with an event list) re-registers the process with every
// event on every activation; static sensitivity costs nothing per activation.

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <vector>

#include <systemc>

#include "sim/kernel/cycle_clock.h"

namespace rtu {

// Spawns `method` as a method process of the current module, sensitive to `events`. Called from
// end_of_elaboration, once the ports the events come from are bound. It also runs once at the
// start of simulation.
template <class Method>
void spawnMethod(const char* name, Method&& method,
                 std::initializer_list<const sc_core::sc_event*> events,
                 const std::vector<const sc_core::sc_event*>& more = {}) {
  sc_core::sc_spawn_options options;
  options.spawn_method();
  for (const sc_core::sc_event* event : events) options.set_sensitivity(event);
  for (const sc_core::sc_event* event : more) options.set_sensitivity(event);
  sc_core::sc_spawn(std::forward<Method>(method), name, &options);
}

// The same, not run at the start of simulation: it reacts only to `events`.
template <class Method>
void spawnReaction(const char* name, Method&& method,
                   std::initializer_list<const sc_core::sc_event*> events) {
  sc_core::sc_spawn_options options;
  options.spawn_method();
  options.dont_initialize();
  for (const sc_core::sc_event* event : events) options.set_sensitivity(event);
  sc_core::sc_spawn(std::forward<Method>(method), name, &options);
}

// A wake-up at the start of a chosen future cycle; setting another cycle replaces it.
class CycleWake {
 public:
  explicit CycleWake(const CycleClock& clock) : clock_(clock) {}

  void at(uint64_t cycle) {
    if (cycle == pending_) return;
    event_.cancel();
    event_.notify(clock_.until(cycle));
    pending_ = cycle;
  }
  void cancel() {
    if (pending_ == kNone) return;
    event_.cancel();
    pending_ = kNone;
  }
  const sc_core::sc_event& event() const { return event_; }

 private:
  static constexpr uint64_t kNone = std::numeric_limits<uint64_t>::max();
  const CycleClock& clock_;
  sc_core::sc_event event_;
  uint64_t pending_ = kNone;
};

}  // namespace rtu
