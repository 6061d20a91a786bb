#pragma once
// The traversal stack of a triangle core: a fixed number of entries in a ring, so that a push onto
// a full stack overwrites the oldest entry instead of failing. That is seed 001's short stack (a
// 4-entry ring whose lost entries a restart from the root recovers) and, with a capacity the tree
// never exceeds, a plain stack (seed 003's BVH, seed 004's 32-entry BIH stack); a traversal that
// cannot restart counts what was dropped, as the SVO core counts its overflows. The storage is
// allocated once, at construction: pushing and popping never allocate.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace rtu {

template <class Entry>
class RingStack {
 public:
  explicit RingStack(int capacity) : slots_(checked(capacity)) {}

  int capacity() const { return static_cast<int>(slots_.size()); }
  int size() const { return size_; }
  bool empty() const { return size_ == 0; }
  // Entries overwritten by pushes onto a full stack since the last clear().
  uint64_t dropped() const { return dropped_; }

  void clear() {
    size_ = 0;
    dropped_ = 0;
  }
  void push(const Entry& entry) {
    top_ = top_ + 1 == capacity() ? 0 : top_ + 1;
    slots_[top_] = entry;
    if (size_ == capacity())
      ++dropped_;
    else
      ++size_;
  }
  // The newest entry, removed. Only when not empty().
  // The newest entry; the stack must not be empty.
  const Entry& top() const { return slots_[top_]; }
  Entry pop() {
    const Entry entry = slots_[top_];
    top_ = top_ == 0 ? capacity() - 1 : top_ - 1;
    --size_;
    return entry;
  }

 private:
  static size_t checked(int capacity) {
    if (capacity < 1)
      throw std::invalid_argument("a traversal stack needs at least one entry, got " +
                                  std::to_string(capacity));
    return static_cast<size_t>(capacity);
  }

  std::vector<Entry> slots_;
  int top_ = 0;  // the newest entry's slot when not empty
  int size_ = 0;
  uint64_t dropped_ = 0;
};

}  // namespace rtu
