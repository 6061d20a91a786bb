#pragma once
// The golden traversal of seed 001's k-d tree (the Tray Racer's ray pipe: S1 §2.6.1 p.9 L155-167,
// §2.6.7 L226-234, §2.6.9 L252-262, §2.6.10 L264-272; the rules exactly as R1's RTL has them,
// specs/001 §2.2 and §3.2) for one ray, as the behaviour of the k-d core (kd_kind.h) and of the
// ray pipe's golden frame: a state machine advanced by step(readWord), one state per step, each
// reading state one word or one aligned 4-word access (kWordsPerRead) of the memory image
// (kd_image.h). The arithmetic is kd_units.h's; the states' cycles kd_timing.h's (cost() sums
// them: with the default cycles, one a state).
//
// States, one step each:
//   SINT   the ray against the scene box (the core's registers): a miss -> OUT
//   NODE   the current node's 2 words (within one access); a leaf -> LIST (or, with no
//          triangle, the list unit's decision at once)
//   TRAV   the plane test and TRAV's action: the next node -> NODE, pushing the far child when
//          both are to be visited; the only child to visit is empty -> POP with t = t_max
//   LIST   the leaf's next list entry (1 word), a triangle id
//   UTTM0-UTTM2  the triangle's 12 words
//   INT    the unit-triangle test and the list unit's replacement; after the leaf's last
//          triangle, the list unit's decision: a hit -> OUT, else POP with t = the leaf's t_max
//   POP    the short stack: its newest entry -> NODE over [t, entry's t_max]; empty and
//          t >= t_max_scene -> OUT (a miss); empty otherwise -> a restart: NODE at the restart
//          node over [t, t_max_scene]
//
// The rules (specs/001 §2.2; R1 RAYTRACER/trav/trav_unit.sv, shortstack/shortstack.sv,
// list/list_unit.sv): the low child is the node + 1, the high child explicit (reading K1). TRAV
// pops when (only low and the low child is empty) or (only high and the high child is empty);
// pushes {far child, t_max} when both children are non-empty and the ray visits both; goes to the
// low child when only low, or low then high with the low child non-empty, or high then low with
// the high child empty, else to the high child; over [t_min, t_max] for only one child,
// [t_min, t_mid] for a non-empty near child, [t_mid, t_max] when the near child is empty. While
// the ray is still searching for its restart node (until its first push), a push makes the node
// the restart node with t_max_scene := t_max, and a visit to both children with the far one
// empty sets t_max_scene := t_max. The stack is a ring of 4 that overwrites its oldest entry
// (S1 §2.6.1; rtu/traversal_stack.h). The list unit replaces its best when a hit's t is not
// greater than the best's (so ties go to the later triangle) or there is no best; at a leaf's end
// the best is a hit if its t <= the leaf's t_max, and otherwise is kept into later leaves.
//
// An any-hit ray (rtu/ray_span.h) is the seed's shadow ray (KdRay::shadow, S1's "shader 2"): SINT
// clamps its t_max to 1 (kd_units.h), and INT ends its leaf at its first hit within the leaf's
// interval (the list unit's decision then ends the ray: the hit is within [t_min, 1]); each of its
// tests waits for the unit's result (the triangle latency), which decides whether it goes on.

#include <array>
#include <cstdint>
#include <stdexcept>

#include "base/float_bits.h"
#include "kinds/kd/kd_image.h"
#include "kinds/kd/kd_timing.h"
#include "kinds/kd/kd_units.h"
#include "rtu/traversal_stack.h"

namespace rtu {

enum class KdState : uint8_t { Idle, Sint, Node, Trav, List, Uttm0, Uttm1, Uttm2, Int, Pop, Out };

// Where the image's sections start, in words, and the scene box the core's registers hold.
struct KdSections {
  uint32_t nodes = 0, lists = 0, uttms = 0;
  std::array<float, 6> box{};
};

inline KdSections sectionsOf(const KdHeader& header) {
  return KdSections{header.nodeBase, header.listBase, header.uttmBase, header.box};
}

struct KdJob {
  KdRay ray;
  KdSections image;
};

// What one ray's traversal counted.
struct KdRayCounts {
  uint32_t nodes = 0;   // node records read, interior and leaf
  uint32_t leaves = 0;  // of which leaves
  uint32_t triangleTests = 0;
  uint32_t restarts = 0;
  uint32_t boxMisses = 0;  // 1 when SINT missed the scene box
  uint32_t pushes = 0;
  uint32_t dropped = 0;   // stack entries overwritten by a push onto a full stack
  uint32_t accesses = 0;  // memory accesses, kWordsPerRead words each
  uint32_t anyHit = 0;    // 1 for an any-hit (shadow) ray
  uint32_t occluded = 0;  // 1 for an any-hit ray that hit

  bool operator==(const KdRayCounts& o) const {
    return nodes == o.nodes && leaves == o.leaves && triangleTests == o.triangleTests &&
           restarts == o.restarts && boxMisses == o.boxMisses && pushes == o.pushes &&
           dropped == o.dropped && accesses == o.accesses && anyHit == o.anyHit &&
           occluded == o.occluded;
  }
};

// The k-d core's settings (the kind's Config, RtuConfig::coreConfig<KdKind>(); the schema's keys
// core.short_stack and the shared units' core.box.latency, core.triangle.latency and
// core.triangle.interval, src/config/config_schema.cpp "addKdSettings").
constexpr int kMaxKdShortStack = 1024;
constexpr uint32_t kMaxKdUnitCycles = 1024;

struct KdTraversalConfig {
  int stackDepth = 4;  // S1 §2.6.9: "the 4-deep stack"
  Division division = Division::Ieee;
  KdTMaxClamp tMaxClamp = KdTMaxClamp::AsBuilt;
  KdCycles cycles;

  // Throws std::invalid_argument naming the setting (core.short_stack, core.box.latency,
  // core.triangle.latency, core.triangle.interval) for a short stack of other than 1 to
  // kMaxKdShortStack entries, units of other than 1 to kMaxKdUnitCycles cycles, or an interval
  // longer than the latency.
  void validate() const;
};

class KdTraversal {
 public:
  static constexpr uint32_t kWordsPerRead = 4;

  explicit KdTraversal(const KdTraversalConfig& config)
      : stack_(config.stackDepth), config_(config) {}

  // The current state's cycles (kd_timing.h), asked before it is stepped.
  uint32_t stateCycles() const {
    switch (state_) {
      case KdState::Sint:
      case KdState::Trav: return config_.cycles.boxLatency;
      case KdState::Int:
        // A shadow ray waits for every test's result: a hit ends it.
        return left_ > 1 && !ray_.shadow ? config_.cycles.triangleInterval
                                         : config_.cycles.triangleLatency;
      default: return 1;
    }
  }
  int stackSize() const { return stack_.size(); }  // the trace's stack signal

  void start(const KdJob& job) {
    ray_ = job.ray;
    image_ = job.image;
    stack_.clear();
    counts_ = {};
    counts_.anyHit = ray_.shadow;
    cost_ = 0;
    hitCur_ = hit_ = false;
    state_ = KdState::Sint;
  }

  KdState state() const { return state_; }
  bool busy() const { return state_ != KdState::Idle && state_ != KdState::Out; }
  bool readsMemory() const {
    switch (state_) {
      case KdState::Node:
      case KdState::List:
      case KdState::Uttm0:
      case KdState::Uttm1:
      case KdState::Uttm2: return true;
      default: return false;
    }
  }
  // The first word the current state reads: NODE's 2 words and LIST's one lie within one access;
  // UTTM0-2 each read a whole access.
  uint32_t memoryAddress() const {
    switch (state_) {
      case KdState::Node: return image_.nodes + node_ * kKdNodeWords;
      case KdState::List: return image_.lists + nextList_;
      case KdState::Uttm0: return uttmAddress();
      case KdState::Uttm1: return uttmAddress() + 4;
      case KdState::Uttm2: return uttmAddress() + 8;
      default: return 0;
    }
  }

  // Forced inline: a state does little, so the call would cost a good part of it.
  template <class ReadWord>
  [[gnu::always_inline]] inline void step(ReadWord&& readWord) {
    const uint32_t cycles = stateCycles();
    if (readsMemory()) ++counts_.accesses;
    switch (state_) {
      case KdState::Sint: sceneBox(); break;
      case KdState::Node: readNode(readWord); break;
      case KdState::Trav: traverse(); break;
      case KdState::List:
        triangle_ = readWord(memoryAddress());
        state_ = KdState::Uttm0;
        break;
      case KdState::Uttm0: readUttm(readWord, 0, KdState::Uttm1); break;
      case KdState::Uttm1: readUttm(readWord, 4, KdState::Uttm2); break;
      case KdState::Uttm2: readUttm(readWord, 8, KdState::Int); break;
      case KdState::Int: intersect(); break;
      case KdState::Pop: pop(); break;
      default: throw std::logic_error("k-d traversal stepped while idle or done");
    }
    cost_ += cycles;
  }
  // The timed cores' name for step (as the SVO core's).
  template <class ReadWord>
  [[gnu::always_inline]] inline void stepInline(ReadWord&& readWord) {
    step(readWord);
  }
  void finish() { state_ = KdState::Idle; }

  bool hit() const { return hit_; }
  float t() const { return tCur_; }
  float u() const { return uCur_; }  // the seed's: u weighs the triangle's A, v its B
  float v() const { return vCur_; }
  uint32_t primitive() const { return triCur_; }  // the hit triangle's id
  uint32_t cost() const { return cost_; }         // its states' cycles (stateCycles each)
  KdRayCounts counts() const {
    KdRayCounts counts = counts_;
    counts.dropped = static_cast<uint32_t>(stack_.dropped());
    return counts;
  }

 private:
  struct Entry {
    uint32_t node = 0;
    float tMax = 0;
  };

  uint32_t uttmAddress() const { return image_.uttms + triangle_ * kKdUttmWords; }

  void sceneBox() {
    const KdInterval box = sceneIntersection(ray_, image_.box, config_.tMaxClamp, config_.division);
    if (box.miss) {
      ++counts_.boxMisses;
      state_ = KdState::Out;
      return;
    }
    visit(0, box.tMin, box.tMax);
    search_ = true;
    restartNode_ = 0;
    tMaxScene_ = box.tMax;
  }

  void visit(uint32_t node, float tMin, float tMax) {
    node_ = node;
    tMin_ = tMin;
    tMax_ = tMax;
    state_ = KdState::Node;
  }

  template <class ReadWord>
  void readNode(ReadWord& readWord) {
    const uint32_t address = memoryAddress();
    const uint32_t words[kKdNodeWords] = {readWord(address), readWord(address + 1)};
    current_ = decodeKdNode(words);
    ++counts_.nodes;
    if (!current_.leaf) {
      state_ = KdState::Trav;
      return;
    }
    ++counts_.leaves;
    nextList_ = current_.listIndex;
    left_ = current_.count;
    if (left_ > 0)
      state_ = KdState::List;
    else
      endLeaf();
  }

  void traverse() {
    const KdPlaneTest p = planeTest(ray_, current_.axis, bitsToFloat(current_.splitBits), tMin_,
                                    tMax_, config_.division);
    const uint32_t low = node_ + 1, high = current_.high;
    const bool lowEmpty = current_.lowEmpty, highEmpty = current_.highEmpty;
    if ((p.onlyLow && lowEmpty) || (p.onlyHigh && highEmpty)) {
      popAt(tMax_);
      return;
    }
    const bool push = !lowEmpty && !highEmpty && (p.lowThenHigh || p.highThenLow);
    if (search_ && push) restartNode_ = node_;
    if (search_ && (push || (p.lowThenHigh && highEmpty) || (p.highThenLow && lowEmpty)))
      tMaxScene_ = tMax_;
    if (push) {
      stack_.push(Entry{p.lowThenHigh ? high : low, tMax_});
      ++counts_.pushes;
      search_ = false;
    }
    const bool toLow = p.onlyLow || (p.lowThenHigh && !lowEmpty) || (p.highThenLow && highEmpty);
    if (p.onlyLow || p.onlyHigh)
      visit(toLow ? low : high, tMin_, tMax_);
    else if ((p.lowThenHigh && !lowEmpty) || (p.highThenLow && !highEmpty))
      visit(toLow ? low : high, tMin_, p.tMid);
    else
      visit(toLow ? low : high, p.tMid, tMax_);
  }

  template <class ReadWord>
  void readUttm(ReadWord& readWord, uint32_t offset, KdState next) {
    const uint32_t address = memoryAddress();
    for (uint32_t i = 0; i < kWordsPerRead && offset + i < kUttmWords; ++i)
      uttm_[offset + i] = readWord(address + i);
    state_ = next;
  }

  // INT, then the list unit: a hit replaces the best unless beyond it (ties: the later triangle).
  void intersect() {
    ++counts_.triangleTests;
    const KdTriangleHit found = intersectUnitTriangle(ray_, unpackUttm(uttm_), config_.division);
    if (found.hit && (!greater32(found.t, tCur_) || !hitCur_)) {
      tCur_ = found.t;
      uCur_ = found.u;
      vCur_ = found.v;
      triCur_ = triangle_;
    }
    hitCur_ = hitCur_ || found.hit;
    ++nextList_;
    // A shadow ray's hit within the leaf's interval answers it.
    if (--left_ > 0 && !(ray_.shadow && found.hit && !greater32(found.t, tMax_)))
      state_ = KdState::List;
    else
      endLeaf();
  }

  // The list unit's decision at a leaf's end: the best so far is the hit if not beyond the leaf.
  void endLeaf() {
    if (hitCur_ && !greater32(tCur_, tMax_)) {
      hit_ = true;
      counts_.occluded = ray_.shadow;
      state_ = KdState::Out;
    } else {
      popAt(tMax_);
    }
  }

  void popAt(float t) {
    tPop_ = t;
    state_ = KdState::Pop;
  }

  void pop() {
    search_ = false;
    if (!stack_.empty()) {
      const Entry entry = stack_.pop();
      visit(entry.node, tPop_, entry.tMax);
    } else if (greaterEqual32(tPop_, tMaxScene_)) {
      state_ = KdState::Out;
    } else {
      ++counts_.restarts;
      visit(restartNode_, tPop_, tMaxScene_);
    }
  }

  RingStack<Entry> stack_;
  KdTraversalConfig config_;
  KdRay ray_;
  KdSections image_;
  KdState state_ = KdState::Idle;
  // The ray's place: the node, its interval, what TRAV read of it.
  uint32_t node_ = 0;
  float tMin_ = 0, tMax_ = 0;
  TrayRacerNode current_;
  // The restart record (shortstack.sv's restart BRAM) and whether the ray still searches for it.
  bool search_ = false;
  uint32_t restartNode_ = 0;
  float tMaxScene_ = 0;
  float tPop_ = 0;  // the t_min a pop or restart gives the next node
  // The leaf being intersected.
  uint32_t nextList_ = 0, left_ = 0, triangle_ = 0;
  UttmWords uttm_{};
  // The list unit's record.
  bool hitCur_ = false, hit_ = false;
  float tCur_ = 0, uCur_ = 0, vCur_ = 0;
  uint32_t triCur_ = 0;
  uint32_t cost_ = 0;
  KdRayCounts counts_;
};

}  // namespace rtu
