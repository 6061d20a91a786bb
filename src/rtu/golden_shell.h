#pragma once
// The untimed shell of any core kind (rtu/core_kind.h): it runs the kind's behaviour through a
// job to its end against an ideal memory (the word in the cycle it is read) and writes the
// result. Every state still costs what the kind's cost() counts, so the result is bit for bit a
// timed core's with ideal memory; a kind's golden model (kinds/svo/golden_model.h) is this shell
// with its own job set-up in front.

#include <cstdint>

namespace rtu {

template <class Kind>
class GoldenShell {
 public:
  using Behaviour = typename Kind::Behaviour;

  GoldenShell(typename Kind::Memory memory, const typename Kind::Config& config)
      : memory_(memory), behaviour_(Kind::behaviour(config)) {}

  // Runs `job` to its end and writes its result, under the id word `idWord`, over `result`.
  void run(uint32_t idWord, const typename Kind::Job& job, typename Kind::Result& result) {
    Kind::start(behaviour_, job);
    const auto read = [this](uint32_t address) { return memory_.read(address); };
    while (behaviour_.busy()) behaviour_.step(read);
    behaviour_.finish();
    Kind::writeResult(idWord, behaviour_, result);
  }

  // The behaviour as the last job left it, for what a kind's result does not carry.
  const Behaviour& behaviour() const { return behaviour_; }
  const typename Kind::Memory& memory() const { return memory_; }

 private:
  typename Kind::Memory memory_;
  Behaviour behaviour_;
};

}  // namespace rtu
