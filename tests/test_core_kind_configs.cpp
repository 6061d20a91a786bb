// Every kind's own settings in one RTU configuration (RtuConfig::coreConfigs): reached by the kind
// through coreConfig<Kind>() and the registry's configOf, checked by validate, and asked by the
// kind-agnostic output link.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <type_traits>

#include "sim/rtu_config.h"
#include "toy_kind.h"

namespace rtu {

TEST_CASE("Kind settings: a kind's Config is reached generically through the RTU's", "[kinds]") {
  RtuConfig config;
  config.coreConfig<SvoKind>().stackFrames = 3;
  config.coreConfig<SvoKind>().format = FixedFormat{40, 20};
  const RtuConfig& read = config;
  CHECK(read.coreConfig<SvoKind>().stackFrames == 3);
  CHECK(CoreKinds::configOf<SvoKind>(read.coreConfigs).format.totalBits == 40);
  // A kind outside the registry (a test's) has its defaults.
  static_assert(std::is_same_v<decltype(read.coreConfig<ToyKind>()), const ToyKind::Config&>);
}

TEST_CASE("Kind settings: validate checks the kind's settings, naming the setting", "[kinds]") {
  RtuConfig config;
  REQUIRE_NOTHROW(validate(config));
  config.coreConfig<SvoKind>().stackFrames = 0;
  CHECK_THROWS_AS(validate(config), std::invalid_argument);
  CHECK_THROWS_WITH(validate(config), "stack depth must be 1 to 64 frames, got 0");
  config = RtuConfig{};
  config.coreConfig<SvoKind>().format = FixedFormat{64, 16};
  CHECK_THROWS_AS(validate(config), std::invalid_argument);
}

TEST_CASE("Kind settings: the output link carries the kind's result records", "[kinds]") {
  RtuConfig config;
  CHECK(config.outputLink().recordBytes == 32);
  config.coreConfig<SvoKind>().format = FixedFormat{40, 20};
  CHECK(config.outputLink().recordBytes == 48);
}

}  // namespace rtu
