#pragma once
// How rtusim's modules decide (issue 9, docs/cycle-semantics.md "Transfers"). A transfer on a
// channel carries its cycle, so a module can decide what happens in a cycle as soon as it knows
// enough, usually long before simulated time gets there. A module is an `Agent`: its decide()
// does everything it can with what it knows and returns; whenever a channel it is on changes (an
// offer, a transfer, a declared readiness), the channel puts it on the pump, which calls the
// agents on it until none is left. No kernel event is involved, so a frame with ideal memory
// costs a few function calls per ray.
//
// Simulated time still matters in two places: the memory serves the traversal cores' requests to
// the shared L2 in cycle order, and where a cycle's requests cannot all be known yet it waits
// for simulated time to reach that cycle (memory_system.h); and the host source offers a record
// only once simulated time is within a look-ahead of its cycle, which keeps the run's memory,
// the trace's reorder window and progress reports bounded. Both wake the pump through SystemC
// processes. The rule that makes this exact: every cycle's decisions are made by simulated time
// that cycle at the latest, so a shared-memory request never arrives behind simulated time, and
// no trace record either.
//
// An agent scheduled with scheduleLast() decides once the others have nothing new: the memory,
// which serves requests from bounds the cores and the scheduler publish as they decide.

#include <cstddef>
#include <vector>

namespace rtu {

class DecisionPump;

class Agent {
 public:
  explicit Agent(DecisionPump& pump) : pump_(pump) {}
  virtual ~Agent() = default;
  // Does what the agent can decide now.
  virtual void decide() = 0;
  // Something changed on the agent's channel `port` (a module with many channels keeps a list of
  // those with news instead of looking at all). Puts the agent on the pump.
  virtual void heard(int port);

 protected:
  DecisionPump& pump() { return pump_; }

 private:
  friend class DecisionPump;
  DecisionPump& pump_;
  bool queued_ = false;
};

class DecisionPump {
 public:
  // Puts `agent` on the queue (once, however often it is asked).
  void schedule(Agent& agent) {
    if (agent.queued_) return;
    agent.queued_ = true;
    queue_.push_back(&agent);
  }
  // Puts `agent` on the queue to decide once every other agent has nothing new: for an agent
  // that reads bounds the others publish (the memory serving shared requests ahead of simulated
  // time), which hold only when no decision is half made.
  void scheduleLast(Agent& agent) {
    if (agent.queued_) return;
    agent.queued_ = true;
    last_.push_back(&agent);
  }
  // Lets the agents decide until none has anything new. Called from within run() (a decision
  // that schedules another agent) it only queues: the outer loop drains.
  void run() {
    if (running_) return;
    running_ = true;
    try {
      for (;;) {
        for (size_t next = 0; next < queue_.size(); ++next) decideOne(*queue_[next]);
        queue_.clear();
        if (last_.empty()) break;
        decideOne(takeLast());
      }
    } catch (...) {
      running_ = false;
      throw;
    }
    running_ = false;
  }
  void runWith(Agent& agent) {
    schedule(agent);
    run();
  }
  // Whether an agent waits to decide other than those deciding last: an agent deciding last that
  // cannot go on lets them decide first, as they may raise the bounds it reads.
  bool othersQueued() const { return !queue_.empty(); }

 private:
  static void decideOne(Agent& agent) {
    agent.queued_ = false;
    agent.decide();
  }
  Agent& takeLast() {
    Agent& agent = *last_.back();
    last_.pop_back();
    return agent;
  }

  std::vector<Agent*> queue_;
  std::vector<Agent*> last_;  // decide when queue_ is drained (in no particular order)
  bool running_ = false;
};

inline void Agent::heard(int) { pump_.schedule(*this); }

}  // namespace rtu
