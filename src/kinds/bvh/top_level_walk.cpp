#include "kinds/bvh/top_level_walk.h"

namespace rtu {

void TopLevelWalk::start(const BvhImage& image, const BvhRay& ray) {
  view_.emplace(image.words);
  ray_ = ray;
  tBest_ = ray.tMax;
  stack_.clear();
  counts_ = {};
  refsLeft_ = 0;
  chosen_.reset();
  const BvhNode root = readNode(0);
  if (test(root).hit) chosen_ = root;
}

std::optional<uint32_t> TopLevelWalk::next(float tBest) {
  tBest_ = tBest;
  while (refsLeft_ == 0)
    if (!advance()) return std::nullopt;
  --refsLeft_;
  ++counts_.instances;
  return view_->ref(nextRef_++);
}

TopLevelCounts TopLevelWalk::counts() const {
  TopLevelCounts counts = counts_;
  counts.dropped = static_cast<uint32_t>(stack_.dropped());
  return counts;
}

BvhNode TopLevelWalk::readNode(uint32_t index) {
  ++counts_.nodes;
  return view_->node(index);
}

BoxHit TopLevelWalk::test(const BvhNode& node) {
  ++counts_.boxTests;
  return slabTest(ray_, node.box, ray_.tMin, tBest_);
}

void TopLevelWalk::enter(const BvhNode& node) {
  if (node.leaf) {
    nextRef_ = node.leftOrFirst;
    refsLeft_ = node.rightOrCount;
    return;
  }
  const BvhNode left = readNode(node.leftOrFirst), right = readNode(node.rightOrCount);
  const BoxHit l = test(left), r = test(right);
  if (l.hit && r.hit) {
    const bool leftFirst = l.tEntry <= r.tEntry;
    stack_.push(leftFirst ? Entry{right, r.tEntry} : Entry{left, l.tEntry});
    ++counts_.pushes;
    chosen_ = leftFirst ? left : right;
  } else if (l.hit || r.hit) {
    chosen_ = l.hit ? left : right;
  }
}

bool TopLevelWalk::advance() {
  if (chosen_) {
    const BvhNode node = *chosen_;
    chosen_.reset();
    enter(node);
    return true;
  }
  while (!stack_.empty()) {
    const Entry entry = stack_.pop();
    ++counts_.pops;
    if (entry.tEntry <= tBest_) {
      enter(entry.node);
      return true;
    }
  }
  return false;
}

}  // namespace rtu
