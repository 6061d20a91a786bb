#pragma once
// A FIFO queue over one growing ring of slots: pushes and pops allocate nothing once the ring
// holds the most elements the queue has had. std::deque allocates and frees a 512-byte block
// every 512 / sizeof(T) elements that pass through it, which for a job of the RTU's core kinds
// (about 200 bytes) is every other job. A popped element stays in its slot until a later push
// overwrites it, so T should own no resources worth freeing early.

#include <cstddef>
#include <utility>
#include <vector>

namespace rtu {

template <class T>
class RingQueue {
 public:
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  T& front() { return slots_[head_]; }
  const T& front() const { return slots_[head_]; }
  T& back() { return slots_[slotOf(size_ - 1)]; }
  const T& back() const { return slots_[slotOf(size_ - 1)]; }
  // The i-th element from the front.
  const T& operator[](size_t i) const { return slots_[slotOf(i)]; }

  void push_back(T&& value) {
    if (size_ == slots_.size()) grow();
    slots_[slotOf(size_)] = std::move(value);
    ++size_;
  }
  void pop_front() {
    head_ = slotOf(1);
    --size_;
  }

 private:
  size_t slotOf(size_t i) const {
    const size_t slot = head_ + i;
    return slot < slots_.size() ? slot : slot - slots_.size();
  }
  // Twice the slots, the elements moved to the front in order.
  void grow() {
    std::vector<T> larger(slots_.empty() ? 4 : 2 * slots_.size());
    for (size_t i = 0; i < size_; ++i) larger[i] = std::move(slots_[slotOf(i)]);
    slots_ = std::move(larger);
    head_ = 0;
  }

  std::vector<T> slots_;
  size_t head_ = 0, size_ = 0;
};

}  // namespace rtu
