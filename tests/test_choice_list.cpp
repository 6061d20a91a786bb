// The choice list of messages (base/choice_list.h).
#include <catch2/catch.hpp>

#include "base/choice_list.h"

using namespace rtu;

TEST_CASE("Choice list: commas between the choices\\, or before the last", "[base]") {
  CHECK(choiceList({}).empty());
  CHECK(choiceList({"svo"}) == "svo");
  CHECK(choiceList({"bvh", "kd"}) == "bvh or kd");
  CHECK(choiceList({"bvh", "bih", "kdtree"}) == "bvh, bih or kdtree");
}
