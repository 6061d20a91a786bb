// The ray pipe's settings (raypipe/raypipe_config.h): the seed's final build as defaults, and
// the settings it cannot take refused by name.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "raypipe/raypipe_config.h"

namespace rtu {

TEST_CASE("The ray pipe's defaults are the seed's final build", "[raypipe]") {
  const RaypipeConfig config;
  CHECK(config.traversalUnits == 1);
  CHECK(config.shortStackDepth == 4);
  CHECK(config.raysInFlight == 512);
  CHECK(config.latency.intersection == 45);
  CHECK(config.latency.travMath == 14);
  CHECK(config.latency.prgInterval == 3);
  CHECK(config.fifo.pixelBuffer == 20);
  CHECK(config.clockMHz == 50.0);
  CHECK_NOTHROW(config.validate());
}

TEST_CASE("Impossible ray pipe settings are refused by name", "[raypipe]") {
  RaypipeConfig config;
  config.raysInFlight = 513;
  CHECK_THROWS_WITH(config.validate(),
                    Catch::Contains("raypipe.rays_in_flight") && Catch::Contains("9-bit rayID"));
  config = {};
  config.shortStackDepth = 0;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("raypipe.short_stack_depth"));
  config = {};
  config.fifo.tarb = 0;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("raypipe.fifo.tarb"));
  config = {};
  config.latency.sintInterval = 0;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("raypipe.latency.sint_interval"));
  config = {};
  config.clockMHz = 0;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("raypipe.clock_mhz"));
}

}  // namespace rtu
