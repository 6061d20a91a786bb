// The workload.* keys (issue 32, docs/workloads.md): a frame's passes and how its secondary rays
// are spawned, checked when set and read back as written.
#include <catch2/catch.hpp>

#include "config/config_schema.h"
#include "config/configuration.h"

namespace rtu {

using Catch::Matchers::Contains;

TEST_CASE("Workload keys reach the run configuration and read back", "[config]") {
  Configuration c;
  c.set("workload.rays", "primary+shadow+ao", ConfigSource::CommandLine);
  c.set("workload.lights", "1,2,3; -4,5.5,-6", ConfigSource::CommandLine);
  c.set("workload.samples", "4", ConfigSource::CommandLine);
  c.set("workload.ao_distance", "0.5", ConfigSource::CommandLine);
  c.set("workload.random_rays", "1000", ConfigSource::CommandLine);
  c.set("workload.seed", "7", ConfigSource::CommandLine);
  c.set("workload.order", "sorted", ConfigSource::CommandLine);
  const RunConfig& v = c.values();
  CHECK(v.rayPasses == "primary+shadow+ao");
  REQUIRE(v.workload.secondary.lights.size() == 2);
  CHECK(v.workload.secondary.lights[1].position == glm::dvec3(-4, 5.5, -6));
  CHECK(v.workload.secondary.samples == 4);
  CHECK(v.workload.secondary.aoDistance == 0.5);
  CHECK(v.workload.randomRays == 1000);
  CHECK(v.workload.secondary.seed == 7);
  CHECK(v.workload.order == RayOrder::Sorted);
  CHECK(findSetting("workload.lights").get(v) == "1,2,3;-4,5.5,-6");
  CHECK(findSetting("workload.order").get(v) == "sorted");
}

TEST_CASE("Area lights and their samples as workload keys", "[config]") {
  Configuration c;
  c.set("workload.lights", "rect:0,3,0:1,0,0:0,0,0.5; disc:1,2,3:0,2,0:0.25; 4,5,6",
        ConfigSource::CommandLine);
  c.set("workload.light_samples", "8", ConfigSource::CommandLine);
  const RunConfig& v = c.values();
  REQUIRE(v.workload.secondary.lights.size() == 3);
  const Light& rect = v.workload.secondary.lights[0];
  CHECK(rect.shape == Light::Shape::Rectangle);
  CHECK(rect.position == glm::dvec3(0, 3, 0));
  CHECK(rect.edgeV == glm::dvec3(0, 0, 0.5));
  const Light& disc = v.workload.secondary.lights[1];
  CHECK(disc.shape == Light::Shape::Disc);
  CHECK(disc.normal == glm::dvec3(0, 1, 0));  // the axis made unit
  CHECK(disc.radius == 0.25);
  CHECK(v.workload.secondary.lightSamples == 8);
  CHECK(findSetting("workload.lights").get(v) ==
        "rect:0,3,0:1,0,0:0,0,0.5;disc:1,2,3:0,1,0:0.25;4,5,6");
  for (const char* bad : {"rect:0,3,0:1,0,0:2,0,0", "disc:0,0,0:0,0,0:1", "disc:0,0,0:0,1,0:-1",
                          "disc:0,0,0:0,1,0", "cone:0,0,0:0,1,0:1"})
    CHECK_THROWS_WITH(c.set("workload.lights", bad, ConfigSource::CommandLine),
                      Contains("workload.lights '") && Contains(bad));
  CHECK_THROWS_WITH(c.set("workload.light_samples", "0", ConfigSource::CommandLine),
                    Contains("workload.light_samples"));
}

TEST_CASE("Workload keys refuse what cannot be spawned, naming the key", "[config]") {
  Configuration c;
  CHECK_THROWS_WITH(c.set("workload.rays", "shadow", ConfigSource::CommandLine),
                    Contains("workload.rays shadow: the first pass is primary"));
  CHECK_THROWS_WITH(c.set("workload.rays", "primary,ao+ao", ConfigSource::CommandLine),
                    Contains("ao twice"));
  CHECK_THROWS_WITH(c.set("workload.samples", "0", ConfigSource::CommandLine),
                    Contains("workload.samples: 0 is out of range 1 .. 1024"));
  CHECK_THROWS_WITH(c.set("workload.ao_distance", "0", ConfigSource::CommandLine),
                    Contains("workload.ao_distance"));
  CHECK_THROWS_WITH(c.set("workload.lights", "1,2", ConfigSource::CommandLine),
                    Contains("workload.lights"));
  CHECK_THROWS_WITH(c.set("workload.order", "sideways", ConfigSource::CommandLine),
                    Contains("pixel|shuffled|sorted"));
}

}  // namespace rtu
