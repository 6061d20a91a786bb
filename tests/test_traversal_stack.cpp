// The triangle cores' ring stack (rtu/traversal_stack.h): last in first out, the oldest entry
// overwritten when full and counted, and a capacity that must be at least one.
#include <catch2/catch.hpp>

#include "rtu/traversal_stack.h"

namespace rtu {

TEST_CASE("Traversal stack: last in, first out within its capacity", "[traversal_stack]") {
  RingStack<int> stack(3);
  CHECK(stack.empty());
  stack.push(1);
  stack.push(2);
  stack.push(3);
  CHECK(stack.size() == 3);
  CHECK(stack.pop() == 3);
  stack.push(4);
  CHECK(stack.pop() == 4);
  CHECK(stack.pop() == 2);
  CHECK(stack.pop() == 1);
  CHECK(stack.empty());
  CHECK(stack.dropped() == 0);
}

TEST_CASE("Traversal stack: a push onto a full stack overwrites the oldest", "[traversal_stack]") {
  RingStack<int> stack(4);  // seed 001's short stack
  for (int i = 1; i <= 7; ++i) stack.push(i);
  CHECK(stack.size() == 4);
  CHECK(stack.dropped() == 3);  // 1, 2 and 3
  CHECK(stack.pop() == 7);
  CHECK(stack.pop() == 6);
  stack.push(8);
  CHECK(stack.pop() == 8);
  CHECK(stack.pop() == 5);
  CHECK(stack.pop() == 4);
  CHECK(stack.empty());
  SECTION("clear forgets entries and drops") {
    stack.push(9);
    stack.clear();
    CHECK(stack.empty());
    CHECK(stack.dropped() == 0);
    stack.push(10);
    CHECK(stack.pop() == 10);
  }
}

TEST_CASE("Traversal stack: one entry holds the newest", "[traversal_stack]") {
  RingStack<int> stack(1);
  stack.push(1);
  stack.push(2);
  CHECK(stack.dropped() == 1);
  CHECK(stack.pop() == 2);
  CHECK(stack.empty());
}

TEST_CASE("Traversal stack: no entry is an error", "[traversal_stack]") {
  CHECK_THROWS_WITH(RingStack<int>(0), "a traversal stack needs at least one entry, got 0");
}

}  // namespace rtu
