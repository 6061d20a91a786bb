#pragma once
// The SVO traversal core of thesis appendix C.4 as a state machine that advances one clock cycle
// per step(). It is the behaviour shared by every model: the golden model runs it to completion,
// a timed model decides when each step happens.
//
// The arithmetic is a policy: FixedArith reproduces the RTL bit for bit, Float64Arith gives the
// float64 reference of the same algorithm. Deliberate departures from the printed RTL are listed in
// docs/thesis-defects.md.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "kinds/svo/fixed_point.h"
#include "kinds/svo/svo_memory.h"
#include "rtu/ray_span.h"

namespace rtu {

enum class CoreState : uint8_t { Idle, Init, Eval, Next, Push, Pop, Out };
const char* toString(CoreState state);

// Fixed-point arithmetic of the RTL: wrapping adds, arithmetic right shift.
struct FixedArith {
  using Value = int64_t;
  FixedFormat format;
  Value add(Value a, Value b) const { return format.wrap(a + b); }
  // Whether add(a, b) wraps: the sum is beyond the format's range.
  bool overflows(Value a, Value b) const {
    return a + b > format.maxRaw() || a + b < format.minRaw();
  }
  // Whether a converted t-value sits at the end of the range: the conversion saturated it.
  bool saturated(Value v) const { return v == format.maxRaw() || v == format.minRaw(); }
  // Whether a node's t-extent on an axis is too small to split into children a step wide.
  static bool unresolved(Value t0, Value t1) { return t1 - t0 < 2; }
  static Value half(Value v) { return v >> 1; }
  Value one() const { return format.one(); }
};

struct Float64Arith {
  using Value = double;
  static Value add(Value a, Value b) { return a + b; }
  static bool overflows(Value, Value) { return false; }
  static bool saturated(Value) { return false; }
  static bool unresolved(Value, Value) { return false; }
  static Value half(Value v) { return v * 0.5; }
  static Value one() { return 1.0; }
};

// The RTL's stack holds 11 frames, enough for 12 octree levels.
constexpr int kRtlStackFrames = 11;
constexpr int kMaxStackFrames = 64;

// Combinational helpers of appendix C.4, on any arithmetic. Ties go to x, then y, as in the
// RTL's if/else-if chains.
template <class Value>
struct AxisValue {
  Value value;
  int axis;
};

template <class Value>
AxisValue<Value> maxComponent(const std::array<Value, 3>& t) {
  if (t[0] >= t[1] && t[0] >= t[2]) return {t[0], 0};
  if (t[1] >= t[0] && t[1] >= t[2]) return {t[1], 1};
  return {t[2], 2};
}

template <class Value>
AxisValue<Value> minComponent(const std::array<Value, 3>& t) {
  if (t[0] <= t[1] && t[0] <= t[2]) return {t[0], 0};
  if (t[1] <= t[0] && t[1] <= t[2]) return {t[1], 1};
  return {t[2], 2};
}

// get_initial_child_idx: the entry plane is the largest t0; each other axis whose midpoint the
// ray has passed on entry sets its index bit (thesis table 4.2, with the RTL's >=).
template <class Value>
[[gnu::always_inline]] inline uint8_t initialChildIndex(const std::array<Value, 3>& t0,
                                                        const std::array<Value, 3>& tm) {
  const int entryAxis = maxComponent(t0).axis;
  uint8_t child = 0;
  for (int k = 0; k < 3; ++k)
    if (k != entryAxis && t0[entryAxis] >= tm[k]) child |= static_cast<uint8_t>(1u << k);
  return child;
}

// get_next_child_idx (thesis table 4.3): the ray leaves the child through its smallest exit
// plane t1; if the child already lies in the upper half along that axis the parent is done and
// the result is 8 (END).
template <class Value>
int nextChildIndex(int child, const std::array<Value, 3>& childT1) {
  const int bit = 1 << minComponent(childT1).axis;
  return child & bit ? 8 : child | bit;
}

template <class Arith>
class TraversalCore {
 public:
  using Value = typename Arith::Value;
  using Vec3 = std::array<Value, 3>;

  explicit TraversalCore(Arith arith = {}, int stackFrames = kRtlStackFrames)
      : arith_(arith), stackFrames_(stackFrames) {
    if (stackFrames < 1 || stackFrames > kMaxStackFrames)
      throw std::invalid_argument("stack depth must be 1 to " + std::to_string(kMaxStackFrames) +
                                  " frames, got " + std::to_string(stackFrames));
  }

  // The job handshake in IDLE: latches the job, the next cycle is INIT. `span`: which part of
  // the ray's line it traces (rtu/ray_span.h; t = 0 at its origin, t = one() at its end).
  void start(const Vec3& t0, const Vec3& t1, uint8_t a, uint32_t root,
             RaySpan span = RaySpan::Line) {
    a_ = a & 7;
    span_ = span;
    stackSize_ = 0;
    cost_ = 0;
    hit_ = false;
    stackOverflow_ = false;
    belowResolution_ = false;
    tOverflow_ = saturatedAxis(t0, t1);
    frame_ = Frame{root, t0, midpoints(t0, t1), t1, 0};
    // get_ray_valid: registered from the job's t-values, so it is ready by the first EVAL.
    rayValid_ = !(maxComponent(t0).value >= minComponent(t1).value);
    // A ray that misses the root cube ends as a miss whatever its midpoints are.
    tOverflow_ = tOverflow_ && rayValid_;
    state_ = CoreState::Init;
  }

  CoreState state() const { return state_; }
  bool busy() const { return state_ != CoreState::Idle && state_ != CoreState::Out; }

  // Whether the current state consumes a memory word: EVAL reads the current descriptor, PUSH
  // through a far pointer reads the far word.
  bool readsMemory() const {
    return state_ == CoreState::Eval ||
           (state_ == CoreState::Push && Descriptor{descriptor_}.far());
  }
  uint32_t memoryAddress() const {
    return state_ == CoreState::Eval ? frame_.entry
                                     : frame_.entry + Descriptor{descriptor_}.childPointer();
  }

  // One clock cycle in INIT, EVAL, NEXT, PUSH or POP. `readWord(address)` supplies the word
  // at memoryAddress(); it is called only when readsMemory().
  template <class ReadWord>
  void step(ReadWord&& readWord) {
    stepInline(readWord);
  }
  // The same, forced inline, for a stepping loop that runs once per simulated state (a timed
  // core's; a call costs a fifth of a state, and whether the compiler inlines step depends on the
  // caller's translation unit). The golden model is faster with step as the compiler chooses.
  template <class ReadWord>
  [[gnu::always_inline]] inline void stepInline(ReadWord&& readWord) {
    ++cost_;
    switch (state_) {
      case CoreState::Init:
        frame_.child = initialChildIndex(frame_.t0, frame_.tm);
        state_ = CoreState::Eval;
        break;
      case CoreState::Eval: evaluate(readWord(frame_.entry)); break;
      case CoreState::Next: next(); break;
      case CoreState::Push:
        push(Descriptor{descriptor_}.far() ? readWord(memoryAddress()) : 0);
        break;
      case CoreState::Pop:
        state_ = CoreState::Next;  // the frame was restored on the NEXT -> POP edge
        break;
      default:
        --cost_;
        throw std::logic_error(std::string("traversal core stepped in state ") + toString(state_));
    }
  }

  // The result handshake in OUT.
  void finish() { state_ = CoreState::Idle; }

  bool hit() const { return hit_; }
  RaySpan span() const { return span_; }
  Value tHit() const { return tHit_; }
  int normalAxis() const { return normalAxis_; }
  uint32_t cost() const { return cost_; }
  bool stackOverflow() const { return stackOverflow_; }
  // The job's t-values were beyond the format's range in a ray that enters the root cube, and the
  // result is unreliable: a midpoint sum wrapped (a camera far from the model), or the conversion
  // saturated a t-value, so the midpoints no longer say where the ray is along that axis (a
  // direction component too small for the range, docs/precision.md "The extremes").
  bool tOverflow() const { return tOverflow_; }
  // The ray descended into a node whose children are less than a step of the format wide on some
  // axis (a tree deeper than the fraction bits resolve): whether it meets them is decided by
  // truncation, and the result is unreliable (docs/precision.md "The extremes").
  bool belowResolution() const { return belowResolution_; }
  // After a hit: the leaf hit, as its parent descriptor's address and its slot there. It names the
  // voxel uniquely in the image, so two arithmetics can be compared on which voxel they hit.
  uint64_t hitVoxel() const {
    return uint64_t{frame_.entry} << 3 | static_cast<uint64_t>(frame_.child ^ a_);
  }
  int stackSize() const { return stackSize_; }
  const Arith& arith() const { return arith_; }

 private:
  struct Frame {
    uint32_t entry;
    Vec3 t0, tm, t1;
    uint8_t child;
  };
  bool saturatedAxis(const Vec3& t0, const Vec3& t1) const {
    for (int k = 0; k < 3; ++k)
      if (arith_.saturated(t0[k]) || arith_.saturated(t1[k])) return true;
    return false;
  }
  // The RTL's adders wrap; a sum that does so is noted (tOverflow), as the midpoint is garbage.
  // Forced inline, as push: with the ray spans' checks in evaluate GCC stopped inlining it and
  // initialChildIndex into the stepping loop (+4 % instructions a cycle-accurate frame).
  [[gnu::always_inline]] inline Vec3 midpoints(const Vec3& t0, const Vec3& t1) {
    for (int k = 0; k < 3; ++k) tOverflow_ = tOverflow_ || arith_.overflows(t0[k], t1[k]);
    return {Arith::half(arith_.add(t0[0], t1[0])), Arith::half(arith_.add(t0[1], t1[1])),
            Arith::half(arith_.add(t0[2], t1[2]))};
  }
  // get_child_t_values
  static Vec3 childT0(const Frame& f) {
    return {f.child & 1 ? f.tm[0] : f.t0[0], f.child & 2 ? f.tm[1] : f.t0[1],
            f.child & 4 ? f.tm[2] : f.t0[2]};
  }
  static Vec3 childT1(const Frame& f) {
    return {f.child & 1 ? f.t1[0] : f.tm[0], f.child & 2 ? f.t1[1] : f.tm[1],
            f.child & 4 ? f.t1[2] : f.tm[2]};
  }
  static int nextChild(const Frame& f) { return nextChildIndex(f.child, childT1(f)); }

  // Forced inline, as push below: the stepping loop's hot path.
  [[gnu::always_inline]] inline void evaluate(uint32_t descriptorWord) {
    if (!rayValid_) {
      hit_ = false;
      state_ = CoreState::Out;
      return;
    }
    if (span_ != RaySpan::Line && outsideSpan()) return;
    const Descriptor descriptor{descriptorWord};
    const int slot = frame_.child ^ a_;
    if (!(descriptor.validMask() >> slot & 1)) {
      state_ = CoreState::Next;
    } else if (descriptor.leafMask() >> slot & 1) {
      const auto entry = maxComponent(childT0(frame_));
      hit_ = true;
      tHit_ = entry.value;
      normalAxis_ = entry.axis;
      state_ = CoreState::Out;
    } else {
      descriptor_ = descriptorWord;  // latched for PUSH (see defect 3 in docs/thesis-defects.md)
      state_ = CoreState::Push;
    }
  }

  // A ray with a span skips a child that ends before its origin (t < 0), as an empty one; an
  // any-hit ray ends as a miss at the first child that begins beyond its end (t > 1): children
  // come front to back, so every later one lies beyond too, and the first leaf the traversal
  // meets within [0, 1] ends it as a hit.
  // Out of line: the thesis' rays (RaySpan::Line) never call it.
  [[gnu::noinline]] bool outsideSpan() {
    if (span_ == RaySpan::AnyHit && maxComponent(childT0(frame_)).value > arith_.one()) {
      hit_ = false;
      state_ = CoreState::Out;
      return true;
    }
    if (minComponent(childT1(frame_)).value < Value{0}) {
      state_ = CoreState::Next;
      return true;
    }
    return false;
  }

  // Forced inline: with three kinds sharing the timed core GCC stopped inlining it into the
  // stepping loop (+8 % instructions a cycle-accurate frame, docs/performance.md).
  [[gnu::always_inline]] inline void push(uint32_t farWord) {
    const Descriptor descriptor{descriptor_};
    if (stackSize_ == stackFrames_) {
      stackOverflow_ = true;
      hit_ = false;
      state_ = CoreState::Out;
      return;
    }
    const uint32_t firstChild = descriptor.far() ? frame_.entry + farWord
                                                 : frame_.entry + descriptor.childPointer();
    const uint32_t childEntry = firstChild + descriptor.childOffset(frame_.child ^ a_);
    const Vec3 t0 = childT0(frame_);
    const Vec3 t1 = childT1(frame_);
    stack_[stackSize_++] = frame_;
    belowResolution_ = belowResolution_ || Arith::unresolved(t0[0], t1[0]) ||
                       Arith::unresolved(t0[1], t1[1]) || Arith::unresolved(t0[2], t1[2]);
    frame_ = Frame{childEntry, t0, midpoints(t0, t1), t1, 0};
    state_ = CoreState::Init;
  }

  void next() {
    const int child = nextChild(frame_);
    if (child < 8) {
      frame_.child = static_cast<uint8_t>(child);
      state_ = CoreState::Eval;
    } else if (stackSize_ == 0) {
      hit_ = false;
      state_ = CoreState::Out;
    } else {
      frame_ = stack_[--stackSize_];
      state_ = CoreState::Pop;
    }
  }

  Arith arith_;
  int stackFrames_;
  CoreState state_ = CoreState::Idle;
  Frame frame_{};
  std::array<Frame, kMaxStackFrames> stack_{};
  int stackSize_ = 0;
  uint8_t a_ = 0;
  RaySpan span_ = RaySpan::Line;
  bool rayValid_ = false;
  uint32_t descriptor_ = 0;
  uint32_t cost_ = 0;
  bool hit_ = false;
  Value tHit_{};
  int normalAxis_ = 0;
  bool stackOverflow_ = false;
  bool tOverflow_ = false;
  bool belowResolution_ = false;
};

// Runs a started core to OUT against an ideal memory (data in the same cycle).
template <class Arith>
void runToCompletion(TraversalCore<Arith>& core, const WordMemory& memory) {
  const auto read = [&memory](uint32_t address) { return memory.read(address); };
  while (core.busy()) core.step(read);
}

}  // namespace rtu
