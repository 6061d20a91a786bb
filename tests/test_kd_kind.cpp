// The k-d core as a registered kind (kinds/kd/kd_kind.h): its job set-up from world-space ray
// records into hardware space through a model header, its states' cycles (kd_timing.h) and
// counters on the hand scene (kd_hand_scene.h) worked out by hand, its settings and their keys,
// and, as its fixture's checkOracle() (test_kd_oracle.cpp's rule, kd_oracle_check.h), the golden
// traversal behind that set-up against the float64 brute force. The equivalence tests over every
// kind run it through every model.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "config/configuration.h"
#include "kd_hand_scene.h"
#include "kd_oracle_check.h"
#include "kind_fixture.h"
#include "span_records.h"

namespace rtu {
namespace {

using Kind = KdKind;

// The hand scene's image at word 8 (so its sections move), then a model header naming it.
struct HandModel {
  std::vector<uint32_t> words = std::vector<uint32_t>(8, 0);
  uint32_t header = 0;

  HandModel() {
    const KdImage image = layOutKd(handKdScene());
    words.insert(words.end(), image.words.begin(), image.words.end());
    header = appendModelHeader(words, ModelPlacement{}, 8);
  }
};

// A world ray whose hardware-space ray (x and y swapped) runs along +x from (0, y, z): in the
// world it runs along +y from (y, 0, z).
RayRecord worldAlongHardwareX(uint32_t id, float y, float z, uint32_t model) {
  RayRecord record;
  record.id = id;
  record.origin = {y, 0, z};
  record.direction = {0, 1, 0};
  record.modelAddress = model;
  return record;
}

KdResult traced(const HandModel& model, const RayRecord& ray, const KdTraversalConfig& own) {
  RtuConfig config = kindConfig<Kind>();
  config.coreConfig<Kind>() = own;
  const std::vector<CoreKindResult> results =
      KindFixture<Kind>::golden(WordMemory(model.words), config, {HostRecord{ray}});
  return std::get<KdResult>(results.at(0));
}

KdTraversalConfig withCycles(int stackDepth, KdCycles cycles) {
  KdTraversalConfig config;
  config.stackDepth = stackDepth;
  config.cycles = cycles;
  return config;
}

}  // namespace

TEST_CASE("k-d kind: a world ray into hardware space, the image's sections from its model",
          "[kd_kind]") {
  const HandModel model;
  JobManagerTiming timing;  // 6 stages, 6 ray stages, 16 cycles a header
  Kind::Setup setup(WordMemory(model.words), timing, KdTraversalConfig{});
  const JobSetUp<KdJob> first = setup.setUp(worldAlongHardwareX(7, 0.75f, 0.5f, model.header));
  CHECK(first.idWord == 7);
  CHECK(first.job.ray.origin == std::array<float, 3>{0, 0.75f, 0.5f});
  CHECK(first.job.ray.direction == std::array<float, 3>{1, 0, 0});
  CHECK_FALSE(first.job.ray.shadow);
  // The hand image's sections (kd_image.h): nodes at 16, lists at 28, UTTMs at 32; here from 8.
  CHECK(first.job.image.nodes == 24);
  CHECK(first.job.image.lists == 36);
  CHECK(first.job.image.uttms == 40);
  CHECK(first.job.image.box == std::array<float, 6>{0, 0, 0, 8, 2, 2});
  // The first ray against a model waits for both headers.
  CHECK(first.headerFetch == 32);
  CHECK(first.latency == 6 + 6 + 32);
  const JobSetUp<KdJob> second = setup.setUp(worldAlongHardwareX(8, 0.75f, 0.5f, model.header));
  CHECK(second.headerFetch == 0);
  CHECK(second.latency == 6 + 6);
  CHECK(KindFixture<Kind>::firstDispatch(timing) == 6 + 6 + 32);
  // A model header that names no k-d image.
  std::vector<uint32_t> words = model.words;
  words[8] = 0;
  Kind::Setup broken(WordMemory(words), timing, KdTraversalConfig{});
  CHECK_THROWS_WITH(broken.setUp(worldAlongHardwareX(1, 0.75f, 0.5f, model.header)),
                    Catch::Contains("is not a k-d image"));
}

// test_kd_traversal.cpp's ray from (0, 0.75, 0.75), now through the kind's set-up: SINT, NODE 0,
// TRAV, NODE 1, TRAV, NODE 2 (leaf of T0), its triangle (LIST, UTTM0-2, INT), POP, NODE 3 (leaf
// of T1, T3), two triangles, POP, NODE 4 (leaf of T2), its triangle: 30 states, a hit on T2 at 7.
// With a box unit of 3 cycles, a triangle unit of latency 7 and interval 2: SINT and the two TRAVs
// take 3 each (9), the five NODEs, two POPs and sixteen fetches 1 each (23), and INT the interval
// for T1 (not its leaf's last) and the latency for T0, T3 and T2 (2 + 3 x 7 = 23): 55 cycles.
TEST_CASE("k-d kind: states' cycles, accesses and counters by hand", "[kd_kind]") {
  const HandModel model;
  const RayRecord ray = worldAlongHardwareX(1, 0.75f, 0.75f, model.header);
  const KdResult states = traced(model, ray, KdTraversalConfig{});
  CHECK(states.hit);
  CHECK(states.primitive == 2);
  CHECK(states.t == 7);
  CHECK(states.cost == 30);  // the golden count of states
  const KdResult timed = traced(model, ray, withCycles(4, KdCycles{3, 7, 2}));
  CHECK(timed.cost == 9 + 23 + 23);
  CHECK(timed.t == 7);
  // Accesses: five NODEs, then LIST and UTTM0-2 per triangle.
  CHECK(timed.counts.accesses == 5 + 4 * 4);
  KdCounters counters;
  Kind::countResult(timed, counters);
  CHECK(counters.kdNodesVisited == 5);
  CHECK(counters.kdTriangleTests == 4);
  CHECK(counters.kdBytesFetched == 21 * 16);
  CHECK(counters.kdRestarts == 0);
  CHECK(counters.kdShortStackDrops == 0);
  // A one-entry stack drops {4, 8} and restarts at node 0: one more NODE (1) and TRAV (3).
  const KdResult shallow = traced(model, ray, withCycles(1, KdCycles{3, 7, 2}));
  CHECK(shallow.cost == 55 + 1 + 3);
  KdCounters restarted;
  Kind::countResult(shallow, restarted);
  CHECK(restarted.kdRestarts == 1);
  CHECK(restarted.kdShortStackDrops == 1);
  CHECK(restarted.kdBytesFetched == 22 * 16);
}

TEST_CASE("k-d kind: each state's cycles as the timed shells ask them", "[kd_kind]") {
  const HandModel model;
  Kind::Setup setup(WordMemory(model.words), JobManagerTiming{}, KdTraversalConfig{});
  const KdJob job = setup.setUp(worldAlongHardwareX(1, 0.75f, 0.75f, model.header)).job;
  KdTraversal traversal(withCycles(4, KdCycles{3, 7, 2}));
  traversal.start(job);
  const WordMemory memory(model.words);
  std::vector<uint32_t> cycles;
  uint32_t sum = 0;
  while (traversal.busy()) {
    cycles.push_back(Kind::stateCycles(traversal));
    sum += cycles.back();
    traversal.step([&memory](uint32_t a) { return memory.read(a); });
  }
  const std::vector<uint32_t> triangle = {1, 1, 1, 1, 7};
  std::vector<uint32_t> expected = {3, 1, 3, 1, 3, 1};
  const auto append = [&expected](const std::vector<uint32_t>& part) {
    expected.insert(expected.end(), part.begin(), part.end());
  };
  append(triangle);
  append({1, 1});
  append({1, 1, 1, 1, 2});
  append(triangle);
  append({1, 1});
  append(triangle);
  CHECK(cycles == expected);
  CHECK(traversal.cost() == sum);
}

TEST_CASE("k-d kind: settings refused by name", "[kd_kind]") {
  KdTraversalConfig config;
  CHECK_NOTHROW(config.validate());
  config.stackDepth = 0;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("core.short_stack"));
  config.stackDepth = 4;
  config.cycles.triangleInterval = 2;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("core.triangle.interval"));
  config.cycles = KdCycles{0, 1, 1};
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("core.box.latency"));
}

TEST_CASE("k-d kind: its settings reach its Config, the units' keys are the BVH's, and none has "
          "an effect with another core",
          "[kd_kind][config]") {
  Configuration c;
  c.set("core.triangle.latency", "9", ConfigSource::CommandLine);
  c.set("core", "kd", ConfigSource::CommandLine);
  c.set("core.triangle.interval", "3", ConfigSource::CommandLine);
  c.set("core.box.latency", "2", ConfigSource::CommandLine);
  c.set("core.short_stack", "2", ConfigSource::CommandLine);
  const KdTraversalConfig& own = c.values().rtu.coreConfig<Kind>();
  CHECK(own.stackDepth == 2);
  CHECK(own.cycles.triangleLatency == 9);
  CHECK(own.cycles.triangleInterval == 3);
  CHECK(own.cycles.boxLatency == 2);
  // One key, both kinds' units, whichever order the core is chosen in.
  CHECK(c.values().rtu.coreConfig<BvhKind<>>().cycles.triangleLatency == 9);
  CHECK(findSetting("core.triangle.latency").get(c.values()) == "9");
  const unsigned uses = kUseModel | kUseArithmetic;
  CHECK(whyIneffective(findSetting("core.short_stack"), c.values(), uses, "render").empty());
  CHECK(whyIneffective(findSetting("core.triangle.latency"), c.values(), uses, "render").empty());
  CHECK_THAT(whyIneffective(findSetting("core.stack_depth"), c.values(), uses, "render"),
             Catch::Contains("the core kind is kd"));
  CHECK_THROWS_WITH(c.set("core.short_stack", "0", ConfigSource::CommandLine),
                    Catch::Contains("core.short_stack"));
  Configuration other;
  other.set("core", "bvh", ConfigSource::CommandLine);
  CHECK_THAT(whyIneffective(findSetting("core.short_stack"), other.values(), uses, "render"),
             Catch::Contains("the core kind is bvh"));
  other.set("core", "bih", ConfigSource::CommandLine);
  CHECK_THAT(whyIneffective(findSetting("core.triangle.latency"), other.values(), uses, "render"),
             Catch::Contains("the core kind is bih"));
}

void KindFixture<KdKind>::checkOracle() {
  // The frame's rays, and the same rays moved into the model taking the nearest hit ahead.
  for (const std::string& scene : scenes()) {
    const Frame f = frame(scene, 6, 64, 48);
    for (bool moved : {false, true}) {
      const std::vector<HostRecord> jobs = moved ? movedIntoModel(f.jobs, RaySpan::Ahead) : f.jobs;
      const RtuConfig config = kindConfig<Kind>();
      const std::vector<CoreKindResult> golden = KindFixture::golden(f.memory(), config, jobs);
      Kind::Setup setup(f.memory(), config.jobManager, KdTraversalConfig{});
      const KdOracleCheck oracle(f.mesh, f.built);
      KdAgreement agreement;
      for (size_t i = 0; i < jobs.size(); ++i) {
        const KdJob job = setup.setUp(std::get<RayRecord>(jobs[i])).job;
        oracle.classify(job.ray, std::get<KdResult>(golden[i]), agreement);
      }
      INFO(scene << (moved ? ", moved in, ahead" : "") << ": " << agreement);
      CHECK(agreement.unexplained == 0);
      CHECK(agreement.same > 64 * 48 / 2);
    }
  }
}

}  // namespace rtu
