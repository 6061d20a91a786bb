// Every core kind's independent oracle (docs/architecture.md, "Independent oracles") against its
// golden model: the equivalence tests run one state machine in every model and cannot see a
// control-flow bug in it, so a kind must bring an oracle that shares no traversal code.

#include <catch2/catch.hpp>

#include "kind_fixture.h"

namespace rtu {

TEMPLATE_LIST_TEST_CASE("The kind's oracle agrees with its golden model on its scenes",
                        "[oracle][voxel-walk]", TestedKinds) {
  KindFixture<TestType>::checkOracle();
}

}  // namespace rtu
