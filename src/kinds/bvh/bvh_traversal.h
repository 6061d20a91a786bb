#pragma once
// The golden traversal of seed 003's BVH (Langr 2016, section 3.2.6, lines 675-681) for one ray,
// as the behaviour of a future BVH core: a state machine advanced by step(readWord), one state per
// step, each reading state one 4-word access (kWordsPerRead) of the memory image. Templated on the
// node layout, as madmann91/bvh and Embree template theirs, and on the primitive intersector.
//
// The seed's rule: both child boxes are tested at the parent; a hit child goes on, the other, if
// also hit, is pushed; neither hit pops; a leaf tests all its triangles; the traversal ends when
// the stack is empty, and a box whose entry lies beyond the nearest hit so far is skipped. What
// the seed leaves open is a setting or a reading (docs/triangles.md): which hit child goes first
// (ChildOrder), and that a hit replaces the best only when strictly nearer, so of equal t the
// first in traversal order wins. An any-hit ray (BvhJob::anyHit, a shadow or occlusion ray:
// rtu/ray_span.h) ends at its first hit within [tMin, tMax], and each of its tests waits for the
// unit's result (the triangle latency), which decides whether the ray goes on.
//
// States, one step each (its cycles: bvh_timing.h; one each by default):
//   ROOT0, ROOT1   the root node's words 0-3 and 4-7
//   ROOT_TEST      the root's box against the ray (1 box test): miss -> OUT
//   LEFT0, LEFT1,  the current inner node's children's words (2 accesses each)
//   RIGHT0, RIGHT1
//   DECIDE         both child boxes tested (2 box tests): go to the nearer hit child and push
//                  the other if hit too; neither -> POP
//   REF            the leaf's next triangle reference (1 word)
//   TRI0-TRI2      the triangle's 12 words
//   TEST           the triangle test; the leaf's last -> POP; an any-hit ray's hit -> OUT
//   INST0-INST4    two-level only (a top level's leaf, BvhJob::instances): the instance's
//                  20-word record (two_level_image.h), 5 accesses
//   XFORM          two-level only: the world ray into the instance's mesh space (the shared
//                  float32 transform, rtu/model_transform.h: t keeps the world ray's units), then
//                  the mesh's BVH from its root (ROOT0) with [tMin, the nearest hit so far]
//   POP            OUT when the stack is empty; otherwise the newest entry, skipped (POP again)
//                  when it begins beyond the nearest hit. In a mesh of a two-level BVH, when the
//                  mesh's own entries are used up: back to the world ray and the top level's
//                  leaf (its next instance, or POP again), in the same cycle
// A node reached from DECIDE or POP is entered without another fetch: its child or leaf words
// came with its parent's fetch (or the stack entry).
//
// Two levels (docs/triangles.md, "Two-level BVH in the core"): a job whose `instances` is set
// walks a top-level BVH (its references name instances) by the same states; a top-level leaf's
// REF reads an instance index, INST0-4 its record, XFORM moves the ray, and the mesh is traversed
// on the same stack; the level is a register (the stack's entries below the mesh's are the top
// level's, counted so that a push onto a full stack, which drops the oldest, drops top-level ones
// first). A hit triangle's id is its mesh id plus the instance's primitive base (record word 15),
// so that it names the triangle in the frame's instances concatenated.

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

#include "base/float_bits.h"
#include "geometry/aabb.h"
#include "geometry/triangle_tests.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_ray.h"
#include "kinds/bvh/bvh_timing.h"
#include "rtu/model_header.h"
#include "rtu/traversal_stack.h"

namespace rtu {

enum class BvhState : uint8_t {
  Idle,
  Root0,
  Root1,
  RootTest,
  Left0,
  Left1,
  Right0,
  Right1,
  Decide,
  Ref,
  Tri0,
  Tri1,
  Tri2,
  Test,
  Inst0,
  Inst1,
  Inst2,
  Inst3,
  Inst4,
  Xform,
  Pop,
  Out
};

// A two-level BVH's instance record (two_level_image.h): 20 words, 5 accesses.
//   0..14   the inverse placement as a model header's words 0-14 (rtu/model_header.h)
//   15      primitive base: added to a hit triangle's id in the mesh
//   16..18  the mesh's sections (BvhSections: nodes, refs, triangles), word addresses
//   19      0
constexpr uint32_t kBvhInstanceWords = 20;

// Which of two hit children the traversal enters first; the other is pushed.
enum class ChildOrder : uint8_t {
  Entry,  // the smaller entry distance, the left child on ties
  Axis,   // by the ray's sign on the axis that separates the children's centres most
};

// Where the image's sections start, in words (bvh_image.h places each on a multiple of 4, so that
// a node and a triangle record begin an access).
struct BvhSections {
  uint32_t nodes = 0, refs = 0, triangles = 0;
};

inline BvhSections sectionsOf(const BvhHeader& header) {
  return BvhSections{header.nodeBase, header.listBase, header.triangleBase};
}

struct BvhJob {
  BvhRay ray;
  BvhSections image;
  bool anyHit = false;  // ends at its first hit within [tMin, tMax] (rtu/ray_span.h)
  // Two-level: the word address of the instance records (`image` is then the top level, whose
  // references name instances); 0 for a one-level BVH.
  uint32_t instances = 0;
};

// What one ray's traversal counted.
struct BvhRayCounts {
  uint32_t nodes = 0;  // node records fetched
  uint32_t boxTests = 0;
  uint32_t triangleTests = 0;
  uint32_t pushes = 0, pops = 0;
  uint32_t dropped = 0;    // stack entries lost to a push onto a full stack
  uint32_t accesses = 0;   // memory accesses, kWordsPerRead words each
  uint32_t anyHit = 0;     // 1 for an any-hit ray
  uint32_t occluded = 0;   // 1 for an any-hit ray that hit
  uint32_t instances = 0;  // instances entered (XFORM), two-level only

  bool operator==(const BvhRayCounts& o) const {
    return nodes == o.nodes && boxTests == o.boxTests && triangleTests == o.triangleTests &&
           pushes == o.pushes && pops == o.pops && dropped == o.dropped && accesses == o.accesses &&
           anyHit == o.anyHit && occluded == o.occluded && instances == o.instances;
  }
};

template <class Layout, class Intersector>
class BvhTraversal {
 public:
  using Words = typename Layout::Words;
  static constexpr uint32_t kWordsPerRead = 4;

  BvhTraversal(int stackDepth, ChildOrder order, BvhCycles cycles = {},
               Intersector intersector = {})
      : stack_(stackDepth), order_(order), cycles_(cycles), intersector_(intersector) {}

  void start(const BvhJob& job) {
    ray_ = job.ray;
    image_ = job.image;
    anyHit_ = job.anyHit;
    top_ = TopRegisters{job.ray, job.image, job.instances};
    inMesh_ = false;
    primitiveBase_ = 0;
    intersector_.prepare(ray_);
    stack_.clear();
    counts_ = {};
    counts_.anyHit = anyHit_;
    cost_ = 0;
    hit_ = false;
    tBest_ = ray_.tMax;
    state_ = BvhState::Root0;
  }

  BvhState state() const { return state_; }
  int stackSize() const { return stack_.size(); }
  // The current state's cycles (bvh_timing.h), asked before it is stepped.
  uint32_t stateCycles() const {
    switch (state_) {
      case BvhState::RootTest:
      case BvhState::Decide: return cycles_.boxLatency;
      case BvhState::Xform: return cycles_.transformLatency;
      case BvhState::Test:
        // An any-hit ray waits for every test's result: a hit ends it.
        return refsLeft_ > 1 && !anyHit_ ? cycles_.triangleInterval : cycles_.triangleLatency;
      default: return 1;
    }
  }
  bool busy() const { return state_ != BvhState::Idle && state_ != BvhState::Out; }
  bool readsMemory() const {
    switch (state_) {
      case BvhState::Root0:
      case BvhState::Root1:
      case BvhState::Left0:
      case BvhState::Left1:
      case BvhState::Right0:
      case BvhState::Right1:
      case BvhState::Ref:
      case BvhState::Tri0:
      case BvhState::Tri1:
      case BvhState::Tri2:
      case BvhState::Inst0:
      case BvhState::Inst1:
      case BvhState::Inst2:
      case BvhState::Inst3:
      case BvhState::Inst4: return true;
      default: return false;
    }
  }
  // The first word the current state reads: an access of kWordsPerRead words starts there, except
  // in REF, which reads the one word within its access.
  uint32_t memoryAddress() const {
    switch (state_) {
      case BvhState::Root0: return nodeAddress(0);
      case BvhState::Root1: return nodeAddress(0) + 4;
      case BvhState::Left0: return nodeAddress(Layout::left(current_));
      case BvhState::Left1: return nodeAddress(Layout::left(current_)) + 4;
      case BvhState::Right0: return nodeAddress(Layout::right(current_));
      case BvhState::Right1: return nodeAddress(Layout::right(current_)) + 4;
      case BvhState::Ref: return image_.refs + nextRef_;
      case BvhState::Tri0: return triangleAddress();
      case BvhState::Tri1: return triangleAddress() + 4;
      case BvhState::Tri2: return triangleAddress() + 8;
      case BvhState::Inst0:
      case BvhState::Inst1:
      case BvhState::Inst2:
      case BvhState::Inst3:
      case BvhState::Inst4:
        return top_.instances + triangle_ * kBvhInstanceWords +
               4 * (static_cast<uint32_t>(state_) - static_cast<uint32_t>(BvhState::Inst0));
      default: return 0;
    }
  }

  // Forced inline: a state does little, so the call would cost a good part of it.
  template <class ReadWord>
  [[gnu::always_inline]] inline void step(ReadWord&& readWord) {
    const uint32_t cycles = stateCycles();
    if (readsMemory()) ++counts_.accesses;
    switch (state_) {
      case BvhState::Root0:
        fetch(readWord, current_, 0);
        state_ = BvhState::Root1;
        break;
      case BvhState::Root1:
        fetch(readWord, current_, 4);
        state_ = BvhState::RootTest;
        break;
      case BvhState::RootTest: testRoot(); break;
      case BvhState::Left0:
        fetch(readWord, left_, 0);
        state_ = BvhState::Left1;
        break;
      case BvhState::Left1:
        fetch(readWord, left_, 4);
        state_ = BvhState::Right0;
        break;
      case BvhState::Right0:
        fetch(readWord, right_, 0);
        state_ = BvhState::Right1;
        break;
      case BvhState::Right1:
        fetch(readWord, right_, 4);
        state_ = BvhState::Decide;
        break;
      case BvhState::Decide: decide(); break;
      case BvhState::Ref:
        triangle_ = readWord(memoryAddress());
        state_ = atTopLevel() ? BvhState::Inst0 : BvhState::Tri0;
        break;
      case BvhState::Tri0:
        readTriangle(readWord, 0);
        state_ = BvhState::Tri1;
        break;
      case BvhState::Tri1:
        readTriangle(readWord, 4);
        state_ = BvhState::Tri2;
        break;
      case BvhState::Tri2:
        readTriangle(readWord, 8);
        state_ = BvhState::Test;
        break;
      case BvhState::Test: test(); break;
      case BvhState::Inst0:
      case BvhState::Inst1:
      case BvhState::Inst2:
      case BvhState::Inst3:
      case BvhState::Inst4: readInstance(readWord); break;
      case BvhState::Xform: transform(); break;
      case BvhState::Pop: pop(); break;
      default: throw std::logic_error("BVH traversal stepped while idle or done");
    }
    cost_ += cycles;
  }
  // The timed cores' name for step (as the SVO core's).
  template <class ReadWord>
  [[gnu::always_inline]] inline void stepInline(ReadWord&& readWord) {
    step(readWord);
  }
  void finish() { state_ = BvhState::Idle; }

  bool hit() const { return hit_; }
  float t() const { return tBest_; }
  float u() const { return u_; }
  float v() const { return v_; }
  uint32_t primitive() const { return primitive_; }  // the hit triangle's source id
  uint32_t cost() const { return cost_; }
  BvhRayCounts counts() const {
    BvhRayCounts counts = counts_;
    counts.dropped = static_cast<uint32_t>(stack_.dropped());
    return counts;
  }

 private:
  // A pushed child: its child or leaf words and where the ray enters its box.
  struct Entry {
    uint32_t word6 = 0, word7 = 0;
    float tEntry = 0;
  };

  uint32_t nodeAddress(uint32_t node) const { return image_.nodes + node * Layout::kWords; }
  uint32_t triangleAddress() const { return image_.triangles + triangle_ * kBvhTriangleWords; }

  template <class ReadWord>
  void fetch(ReadWord& readWord, Words& node, uint32_t offset) {
    const uint32_t address = memoryAddress();
    for (uint32_t i = 0; i < kWordsPerRead; ++i) node[offset + i] = readWord(address + i);
    if (offset == 0) ++counts_.nodes;
  }
  template <class ReadWord>
  void readTriangle(ReadWord& readWord, uint32_t offset) {
    const uint32_t address = memoryAddress();
    for (uint32_t i = 0; i < kWordsPerRead; ++i) triangleWords_[offset + i] = readWord(address + i);
  }

  // The slab test against [tMin, tBest] (bvh_ray.h).
  BoxHit slab(const Aabb<float>& box) {
    ++counts_.boxTests;
    return slabTest(ray_, box, ray_.tMin, tBest_);
  }

  void testRoot() {
    if (slab(Layout::box(current_)).hit)
      enter(current_[6], current_[7]);
    else if (inMesh_)
      leaveMesh();
    else
      state_ = BvhState::Out;
  }

  bool atTopLevel() const { return top_.instances != 0 && !inMesh_; }

  template <class ReadWord>
  void readInstance(ReadWord& readWord) {
    const uint32_t offset = memoryAddress() - top_.instances - triangle_ * kBvhInstanceWords;
    for (uint32_t i = 0; i < kWordsPerRead; ++i)
      instanceWords_[offset + i] = readWord(memoryAddress() + i);
    state_ = static_cast<BvhState>(static_cast<uint32_t>(state_) + 1);  // INST4 -> XFORM
  }

  // XFORM: the world ray into the instance's mesh space; the mesh from its root. The top level's
  // leaf goes on with its next reference when the mesh is done (leaveMesh).
  void transform() {
    ModelHeaderWords header{};
    std::copy_n(instanceWords_.begin(), kModelHeaderWords, header.begin());
    const ModelHeader placement = decodeModelHeader(header);
    RayRecord world;
    for (int k = 0; k < 3; ++k) {
      world.origin[k] = top_.ray.origin[k];
      world.direction[k] = top_.ray.direction[k];
    }
    const ModelSpaceRay model = toModelSpace(world, placement);
    ray_ = makeBvhRay(Vec3<float>(model.origin[0], model.origin[1], model.origin[2]),
                      Vec3<float>(model.direction[0], model.direction[1], model.direction[2]),
                      top_.ray.tMin, tBest_);
    intersector_.prepare(ray_);
    image_ = BvhSections{instanceWords_[16], instanceWords_[17], instanceWords_[18]};
    primitiveBase_ = instanceWords_[15];
    top_.nextRef = nextRef_ + 1;
    top_.refsLeft = refsLeft_ - 1;
    top_.entries = stack_.size();
    inMesh_ = true;
    ++counts_.instances;
    state_ = BvhState::Root0;
  }

  // Back to the world ray and the top level's leaf.
  void leaveMesh() {
    inMesh_ = false;
    ray_ = top_.ray;
    intersector_.prepare(ray_);
    image_ = top_.image;
    nextRef_ = top_.nextRef;
    refsLeft_ = top_.refsLeft;
    state_ = refsLeft_ > 0 ? BvhState::Ref : BvhState::Pop;
  }

  void push(const Entry& entry) {
    // A full stack drops its oldest entry: the top level's, while a mesh's are above them.
    if (stack_.size() == stack_.capacity() && top_.entries > 0) --top_.entries;
    stack_.push(entry);
  }

  // Goes into the node whose child or leaf words are `word6`, `word7`.
  void enter(uint32_t word6, uint32_t word7) {
    current_[6] = word6;
    current_[7] = word7;
    if (Layout::leaf(current_)) {
      nextRef_ = Layout::first(current_);
      refsLeft_ = Layout::count(current_);
      state_ = refsLeft_ > 0 ? BvhState::Ref : BvhState::Pop;
    } else {
      state_ = BvhState::Left0;
    }
  }

  void decide() {
    const BoxHit l = slab(Layout::box(left_)), r = slab(Layout::box(right_));
    if (l.hit && r.hit) {
      const bool leftFirst = leftBeforeRight(l, r);
      const Words& near = leftFirst ? left_ : right_;
      const Words& far = leftFirst ? right_ : left_;
      push(Entry{far[6], far[7], leftFirst ? r.tEntry : l.tEntry});
      ++counts_.pushes;
      enter(near[6], near[7]);
    } else if (l.hit || r.hit) {
      const Words& only = l.hit ? left_ : right_;
      enter(only[6], only[7]);
    } else {
      state_ = BvhState::Pop;
    }
  }

  bool leftBeforeRight(const BoxHit& l, const BoxHit& r) const {
    if (order_ == ChildOrder::Entry) return l.tEntry <= r.tEntry;
    const Vec3<float> separation = Layout::box(right_).centre() - Layout::box(left_).centre();
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(separation[k]) > std::abs(separation[axis])) axis = k;
    // Entering along the axis's direction meets the child with the smaller centre first.
    return (ray_.direction[axis] >= 0) == (separation[axis] >= 0);
  }

  void test() {
    ++counts_.triangleTests;
    const auto vertex = [this](int i) {
      return Vec3<float>(bitsToFloat(triangleWords_[3 * i]), bitsToFloat(triangleWords_[3 * i + 1]),
                         bitsToFloat(triangleWords_[3 * i + 2]));
    };
    const auto found =
        intersector_.intersect(ray_, vertex(0), vertex(1), vertex(2), ray_.tMin, tBest_);
    if (found && (!hit_ || found->t < tBest_)) {
      hit_ = true;
      tBest_ = found->t;
      u_ = found->u;
      v_ = found->v;
      primitive_ = triangleWords_[9] + primitiveBase_;
    }
    ++nextRef_;
    state_ = --refsLeft_ > 0 ? BvhState::Ref : BvhState::Pop;
    if (anyHit_ && hit_) {  // the first hit within the segment answers an any-hit ray
      counts_.occluded = 1;
      state_ = BvhState::Out;
    }
  }

  void pop() {
    if (inMesh_ && stack_.size() == top_.entries) {
      leaveMesh();
      return;
    }
    if (stack_.empty()) {
      state_ = BvhState::Out;
      return;
    }
    const Entry entry = stack_.pop();
    ++counts_.pops;
    if (entry.tEntry <= tBest_) enter(entry.word6, entry.word7);  // else POP again
  }

  // The top level's registers while a mesh is traversed: the world ray, the top level's image, its
  // leaf's next reference and count, and its entries at the bottom of the stack.
  struct TopRegisters {
    BvhRay ray;
    BvhSections image;
    uint32_t instances = 0;
    uint32_t nextRef = 0, refsLeft = 0;
    int entries = 0;
  };

  RingStack<Entry> stack_;
  ChildOrder order_;
  BvhCycles cycles_;
  Intersector intersector_;
  BvhRay ray_;
  BvhSections image_;
  BvhState state_ = BvhState::Idle;
  bool anyHit_ = false;
  Words current_{}, left_{}, right_{};
  uint32_t nextRef_ = 0, refsLeft_ = 0, triangle_ = 0;
  std::array<uint32_t, kBvhTriangleWords> triangleWords_{};
  std::array<uint32_t, kBvhInstanceWords> instanceWords_{};
  TopRegisters top_;
  bool inMesh_ = false;
  uint32_t primitiveBase_ = 0;
  bool hit_ = false;
  float tBest_ = 0, u_ = 0, v_ = 0;
  uint32_t primitive_ = 0;
  uint32_t cost_ = 0;
  BvhRayCounts counts_;
};

}  // namespace rtu
