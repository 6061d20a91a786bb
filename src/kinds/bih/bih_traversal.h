#pragma once
// The golden traversal of seed 004's BIH for one ray, as the behaviour of a future BIH core: the
// finite state machine of Table 3.1 (S4 §3.4 p.43 L570-587) and Listing A.3 (p.57ff; spec 004
// §4.4), state for state, advanced by step(readWord), followed by the triangle states that feed
// the intersection unit. Every reading state reads within one aligned 4-word access.
//
// Distances are Listing A.3's: t_a = ((plane - pos_a) idir_a)(78 downto C), a floor, on the BIH's
// own scale (the C99 listing's idir doubles it, grid.h), so they are compared only with each
// other. States, one step each:
//   AABB   tmin = 0; tmax = the smallest exit distance of the scene box [0, upper] (the origin lies
//          inside it: rays are clipped before quantisation, S4 §2.1.2 L287); tmax < 0 -> OUT
//          (done), else the root -> NODE
//   NODE   reads the node triple. A leaf (axis 11) -> LEAF. Otherwise on its axis
//          tx = (clip1 - pos) idir and ty = (clip0 - pos) idir; dist0, the near child's exit, is
//          ty when idir >= 0 and tx otherwise, and dist1, the far child's entry, the other;
//          the near child is c when idir >= 0, else c + 1 -> INNER
//   INNER  the listing's four cases with its exact comparisons:
//            dist0 < tmin and dist1 > tmax    both missed: POP, or OUT when the stack is empty
//            dist0 >= tmin and dist1 > tmax   near only: tmax = min(tmax, dist0) -> NODE
//            dist0 < tmin and dist1 <= tmax   far only: tmin = max(tmin, dist1) -> NODE (the
//                                             OCR kept only `state := node_s`; read as the plan
//                                             says, C13)
//            otherwise                        push {far, max(tmin, dist1), tmax}, then the near
//                                             child with tmax = min(tmax, dist0) -> PUSH
//   PUSH   the near child -> NODE (the cycle the stack write took the RAM port, A.3 push_s)
//   POP    the newest entry's node, tmin and tmax -> NODE (the stack is the core's own RAM, not
//          the image); with the early-out option, an entry beginning beyond the nearest hit is
//          dropped instead (POP again, or OUT)
//   LEAF   one triangle number (29 bits) per state, as leaf_s emits tri_num -> TRI0
//   TRI0-2 the triangle's 12-word record, an access each -> TEST
//   TEST   the kernel; a hit at t <= tBest replaces the best (the later of equal t). The leaf's
//          next triangle -> LEAF; after its last POP, or OUT when the stack is empty
// An any-hit ray (BihJob::anyHit, rtu/ray_span.h) starts with tBest at its segment's end, so
// only a hit within the segment counts, AABB's tmax ends there too, and its first hit ends it:
// TEST -> OUT, each of its tests waiting for the unit's result.
// There is no early-out by default (S4 §3.4 L577: "not implemented"); the result does not depend
// on when hits arrive, since TEST reduces them in the order LEAF emitted them.
//
// Cycles (bih_timing.h): one a state, but TEST, which issues the test to the pipelined triangle
// unit and takes its initiation interval, and the ray's last state, which also waits until the
// last issued test's result is out (the unit's latency after its issue).

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

#include "kinds/bih/bih_image.h"
#include "kinds/bih/bih_timing.h"
#include "kinds/bih/fixed_arith.h"
#include "kinds/bih/fixed_kernels.h"
#include "kinds/bih/grid.h"
#include "rtu/traversal_stack.h"

namespace rtu {

enum class BihState : uint8_t {
  Idle,
  Aabb,
  Node,
  Inner,
  Push,
  Pop,
  Leaf,
  Tri0,
  Tri1,
  Tri2,
  Test,
  Out
};

// What a job needs of the image: where its sections start, how wide node indices are, the scene
// box on the grid (the VHDL's aabb constants, C15) and the records' arithmetic.
struct BihScene {
  uint32_t nodes = 0, list = 0, triangles = 0;
  BihIndexWidth width = BihIndexWidth::Seed;
  GridPoint upper{};
  FixedTriangleFormat format;
};

inline BihScene sceneOf(const BihHeader& header) {
  return BihScene{header.nodeBase, header.listBase,     header.triangleBase,
                  header.width(),  header.sceneUpper(), decodeFormat(header.format)};
}

struct BihJob {
  GridRay ray;  // clipped and quantised on the image's grid (SceneGrid::quantise)
  BihScene scene;
  bool missesBox = false;  // the ray misses the scene box: AABB ends it (no grid ray exists)
  // An any-hit ray (rtu/ray_span.h): ends at its first hit, at grid t <= tLimit (the end of its
  // segment on the grid ray).
  bool anyHit = false;
  int64_t tLimit = kC99NoHitYet;
};

// What one ray's traversal counted.
struct BihRayCounts {
  uint32_t nodes = 0;  // NODE states: node triples read
  uint32_t pushes = 0, pops = 0;
  uint32_t leaves = 0;
  uint32_t triangleTests = 0;
  uint32_t errBits = 0;     // tests ended by the VHDL divider's error bit
  uint32_t tOverflows = 0;  // C99 quotients beyond int (C7)
  uint32_t dropped = 0;     // stack entries lost to a push onto the full 32-entry stack
  uint32_t accesses = 0;    // memory accesses, kWordsPerRead words each
  uint32_t anyHit = 0;      // 1 for an any-hit ray
  uint32_t occluded = 0;    // 1 for an any-hit ray that hit

  bool operator==(const BihRayCounts& o) const {
    return nodes == o.nodes && pushes == o.pushes && pops == o.pops && leaves == o.leaves &&
           triangleTests == o.triangleTests && errBits == o.errBits && tOverflows == o.tOverflows &&
           dropped == o.dropped && accesses == o.accesses && anyHit == o.anyHit &&
           occluded == o.occluded;
  }
};

// The seed's stack: 32 entries at 992-1023 (A.3); the builder keeps depth <= 31 (bih_builder.h).
inline constexpr int kBihStackEntries = 32;

template <class Intersector>
class BihTraversal {
 public:
  static constexpr uint32_t kWordsPerRead = 4;

  explicit BihTraversal(bool earlyOut, BihCycles cycles = {}, Intersector intersector = {})
      : stack_(kBihStackEntries), earlyOut_(earlyOut), cycles_(cycles), intersector_(intersector) {}

  void start(const BihJob& job) {
    ray_ = job.ray;
    scene_ = job.scene;
    missesBox_ = job.missesBox;
    anyHit_ = job.anyHit;
    lastIssue_ = kNoIssue;
    stack_.clear();
    counts_ = {};
    counts_.anyHit = anyHit_;
    cost_ = 0;
    hit_ = false;
    tBest_ = anyHit_ ? std::min(job.tLimit, kC99NoHitYet) : kC99NoHitYet;
    state_ = BihState::Aabb;
  }

  BihState state() const { return state_; }
  int stackSize() const { return stack_.size(); }  // the trace's stack signal
  // The current state's cycles (bih_timing.h), asked before it is stepped: TEST the unit's
  // initiation interval, the ray's last state until the last issued test's result is out.
  uint32_t stateCycles() const {
    const bool test = state_ == BihState::Test;
    // An any-hit ray's test waits for its result too: a hit ends the ray.
    if (!endsRay() && !(test && anyHit_)) return test ? cycles_.triangleInterval : 1;
    const uint64_t issued = test ? cost_ : lastIssue_;
    // No test issued, or its result out already: the state's own cycle.
    if (issued == kNoIssue || issued + cycles_.triangleLatency <= cost_ + 1) return 1;
    return static_cast<uint32_t>(issued + cycles_.triangleLatency - cost_);
  }
  bool busy() const { return state_ != BihState::Idle && state_ != BihState::Out; }
  bool readsMemory() const {
    switch (state_) {
      case BihState::Node:
      case BihState::Leaf:
      case BihState::Tri0:
      case BihState::Tri1:
      case BihState::Tri2: return true;
      default: return false;
    }
  }
  // The first word the current state reads: the node triple's, the list entry's, or a record's
  // access (LEAF reads the one word within its access).
  uint32_t memoryAddress() const {
    switch (state_) {
      case BihState::Node: return scene_.nodes + kBihNodeWords * node_;
      case BihState::Leaf: return scene_.list + nextEntry_;
      case BihState::Tri0: return triangleAddress();
      case BihState::Tri1: return triangleAddress() + 4;
      case BihState::Tri2: return triangleAddress() + 8;
      default: return 0;
    }
  }

  template <class ReadWord>
  void step(ReadWord&& readWord) {
    const uint32_t cycles = stateCycles();
    if (readsMemory()) ++counts_.accesses;
    switch (state_) {
      case BihState::Aabb: aabb(); break;
      case BihState::Node: readNode(readWord); break;
      case BihState::Inner: inner(); break;
      case BihState::Push:
        node_ = nearChild_;
        state_ = BihState::Node;
        break;
      case BihState::Pop: pop(); break;
      case BihState::Leaf:
        triangle_ = readWord(memoryAddress()) & ((1u << kBihTriangleNumberBits) - 1);
        ++nextEntry_;
        --entriesLeft_;
        state_ = BihState::Tri0;
        break;
      case BihState::Tri0: readRecord(readWord, 0, BihState::Tri1); break;
      case BihState::Tri1: readRecord(readWord, 4, BihState::Tri2); break;
      case BihState::Tri2: readRecord(readWord, 8, BihState::Test); break;
      case BihState::Test: test(); break;
      default: throw std::logic_error("BIH traversal stepped while idle or done");
    }
    cost_ += cycles;
  }
  // The timed cores' name for step.
  template <class ReadWord>
  void stepInline(ReadWord&& readWord) {
    step(readWord);
  }
  void finish() { state_ = BihState::Idle; }

  bool hit() const { return hit_; }
  int64_t t() const { return tBest_; }  // grid units (GridRay::worldT maps it back)
  double worldT() const { return ray_.worldT(tBest_); }  // t along the job's world-space ray
  int64_t u() const { return u_; }  // the seed's u, v at scale 2^(m-1+E) (fixed_kernels.h)
  int64_t v() const { return v_; }
  uint32_t primitive() const { return primitive_; }  // the hit triangle's source id
  uint32_t cost() const { return cost_; }            // its states' cycles
  const BihRayCounts& counts() const { return counts_; }

 private:
  // A pushed far child: its node and its interval along the ray.
  struct Entry {
    uint32_t node = 0;
    int64_t tmin = 0, tmax = 0;
  };

  static constexpr uint64_t kNoIssue = UINT64_MAX;

  // Whether the current state, stepped, ends the ray (OUT next).
  bool endsRay() const {
    switch (state_) {
      case BihState::Inner: return dist0_ < tmin_ && dist1_ > tmax_ && stack_.empty();
      case BihState::Test: return entriesLeft_ == 0 && stack_.empty();
      case BihState::Pop:
        return earlyOut_ && hit_ && stack_.size() == 1 && bihDistance(tBest_) < stack_.top().tmin;
      case BihState::Node: return false;  // a leaf of count 0 (refused by the validator) aside
      default: return false;
    }
  }

  uint32_t triangleAddress() const { return scene_.triangles + kBihTriangleWords * triangle_; }

  // ((plane - pos) idir)(78 downto C): the BIH distance to an axis plane, floored.
  int64_t distance(int64_t plane, uint32_t axis) const {
    return static_cast<int64_t>(
        floorShift(Int128(plane - ray_.origin[axis]) * ray_.idir[axis], scene_.format.C));
  }
  bool negative(uint32_t axis) const { return ray_.idir[axis] < 0; }  // A.3: idir's sign bit

  void aabb() {
    tmin_ = 0;
    tmax_ = INT64_MAX;
    for (uint32_t k = 0; k < 3; ++k)
      tmax_ = std::min(tmax_, distance(negative(k) ? 0 : scene_.upper[k], k));
    // An any-hit ray's segment ends at tBest (a grid unit on, for the distances' floors).
    if (anyHit_) tmax_ = std::min(tmax_, bihDistance(tBest_ + 1));
    node_ = 0;
    state_ = missesBox_ || tmax_ < 0 ? BihState::Out : BihState::Node;
  }

  template <class ReadWord>
  void readNode(ReadWord& readWord) {
    const uint32_t address = memoryAddress();
    const uint32_t words[3] = {readWord(address), readWord(address + 1), readWord(address + 2)};
    const BihNode node = decodeNode(words, scene_.width);
    ++counts_.nodes;
    if (node.leaf()) {
      ++counts_.leaves;
      nextEntry_ = node.index;
      entriesLeft_ = node.count();
      // A count of 0, which the validator refuses, would wrap the listing's counter: leave.
      if (entriesLeft_ == 0) return popOrDone();
      state_ = BihState::Leaf;
      return;
    }
    const int64_t tx = distance(node.clip1, node.axis), ty = distance(node.clip0, node.axis);
    const bool down = negative(node.axis);
    dist0_ = down ? tx : ty;
    dist1_ = down ? ty : tx;
    nearChild_ = down ? node.index + 1 : node.index;
    farChild_ = down ? node.index : node.index + 1;
    state_ = BihState::Inner;
  }

  void inner() {
    const bool nearMissed = dist0_<tmin_, farMissed = dist1_> tmax_;
    if (nearMissed && farMissed) return popOrDone();
    state_ = BihState::Node;
    if (farMissed) {
      tmax_ = std::min(tmax_, dist0_);
      node_ = nearChild_;
    } else if (nearMissed) {
      tmin_ = std::max(tmin_, dist1_);
      node_ = farChild_;
    } else {
      counts_.dropped += stack_.size() == stack_.capacity();
      stack_.push(Entry{farChild_, std::max(tmin_, dist1_), tmax_});
      ++counts_.pushes;
      tmax_ = std::min(tmax_, dist0_);
      state_ = BihState::Push;
    }
  }

  void popOrDone() { state_ = stack_.empty() ? BihState::Out : BihState::Pop; }

  void pop() {
    const Entry entry = stack_.pop();
    ++counts_.pops;
    if (earlyOut_ && hit_ && bihDistance(tBest_) < entry.tmin) return popOrDone();
    node_ = entry.node;
    tmin_ = entry.tmin;
    tmax_ = entry.tmax;
    state_ = BihState::Node;
  }
  // A grid t on the BIH's scale: the C99 listing's idir doubles distances (grid.h).
  int64_t bihDistance(int64_t t) const {
    return scene_.format.listing == FixedListing::C99 ? 2 * t : t;
  }

  template <class ReadWord>
  void readRecord(ReadWord& readWord, uint32_t offset, BihState next) {
    const uint32_t address = memoryAddress();
    for (uint32_t i = 0; i < kWordsPerRead; ++i) record_[offset + i] = readWord(address + i);
    state_ = next;
  }

  void test() {
    ++counts_.triangleTests;
    lastIssue_ = cost_;
    const ProjectedTriangle triangle = fromWords(record_);
    const FixedTest result = intersector_.test(scene_.format, ray_, triangle, tBest_);
    counts_.errBits += result.verdict == FixedVerdict::DividerError;
    counts_.tOverflows += result.verdict == FixedVerdict::TOverflow;
    if (result.hit()) {
      hit_ = true;
      tBest_ = result.t;
      u_ = result.u;
      v_ = result.v;
      primitive_ = triangle.source;
    }
    if (anyHit_ && hit_) {  // the first hit within the segment answers an any-hit ray
      counts_.occluded = 1;
      state_ = BihState::Out;
    } else if (entriesLeft_ > 0)
      state_ = BihState::Leaf;
    else
      popOrDone();
  }

  RingStack<Entry> stack_;
  bool earlyOut_;
  BihCycles cycles_;
  Intersector intersector_;
  bool missesBox_ = false;
  bool anyHit_ = false;
  uint64_t lastIssue_ = kNoIssue;  // the cost when the last test issued
  GridRay ray_;
  BihScene scene_;
  BihState state_ = BihState::Idle;
  uint32_t node_ = 0, nearChild_ = 0, farChild_ = 0;
  int64_t tmin_ = 0, tmax_ = 0, dist0_ = 0, dist1_ = 0;
  uint32_t nextEntry_ = 0, entriesLeft_ = 0, triangle_ = 0;
  std::array<uint32_t, kBihTriangleWords> record_{};
  bool hit_ = false;
  int64_t tBest_ = 0, u_ = 0, v_ = 0;
  uint32_t primitive_ = 0;
  uint32_t cost_ = 0;
  BihRayCounts counts_;
};

}  // namespace rtu
