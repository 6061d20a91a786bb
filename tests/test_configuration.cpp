// The configuration schema: parsing, files, presets, errors that name the key, the round trip of
// config --dump, and sweep expansion.

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>

#include "config/configuration.h"
#include "config/sweep_points.h"
#include "config/sweep_spec.h"
#include "kinds/bih/bih_config.h"
#include "kinds/registry.h"

using namespace rtu;
using Catch::Matchers::Contains;

// Every point of a sweep, computed one by one.
std::vector<rtu::Configuration> allPoints(const rtu::SweepSpec& spec,
                                          const rtu::Configuration& base) {
  const rtu::SweepPoints points(spec, base);
  std::vector<rtu::Configuration> all;
  for (size_t i = 0; i < points.size(); ++i) all.push_back(points.at(i));
  return all;
}

TEST_CASE("Sizes take binary and decimal units", "[config]") {
  CHECK(parseBytes("4096", "k") == 4096);
  CHECK(parseBytes("4KiB", "k") == 4096);
  CHECK(parseBytes("1 MiB", "k") == 1048576);
  CHECK(parseBytes("2GiB", "k") == 2147483648ull);
  CHECK(parseBytes("1kB", "k") == 1000);
  CHECK_THROWS_WITH(parseBytes("4QiB", "memory.l1.size"), Contains("memory.l1.size"));
  CHECK_THROWS(parseBytes("1.5", "k"));
  CHECK(formatBytes(4096) == "4KiB");
  CHECK(formatBytes(3 * 1048576) == "3MiB");
  CHECK(formatBytes(1000) == "1000");
}

TEST_CASE("Settings reach the run configuration by hierarchical name", "[config]") {
  Configuration c;
  c.set("cores", "4", ConfigSource::CommandLine);
  c.set("memory.kind", "cached", ConfigSource::CommandLine);
  c.set("memory.l1.size", "16KiB", ConfigSource::CommandLine);
  c.set("memory.l2.replacement", "fifo", ConfigSource::CommandLine);
  c.set("scheduler", "rr", ConfigSource::CommandLine);
  c.set("camera.position", "1,2,3", ConfigSource::CommandLine);
  c.set("format.conversion", "exact", ConfigSource::CommandLine);
  const RunConfig& v = c.values();
  CHECK(v.rtu.cores == 4);
  CHECK_FALSE(v.rtu.memory.ideal);
  CHECK(v.rtu.memory.l1.sizeBytes == 16384);
  CHECK(v.rtu.memory.l2.replacement == Replacement::Fifo);
  CHECK(v.rtu.scheduler == SchedulerPolicy::RoundRobin);
  CHECK(v.camera.position == glm::dvec3(1, 2, 3));
  CHECK(v.rtu.coreConfig<SvoKind>().conversion == FloatConversion::Exact);
  CHECK(c.source("cores") == ConfigSource::CommandLine);
  CHECK(c.source("width") == ConfigSource::Default);
}

TEST_CASE("An unknown key names the nearest known key, a bad value names key and range",
          "[config]") {
  Configuration c;
  CHECK_THROWS_WITH(c.set("memory.l1.sise", "4KiB", ConfigSource::CommandLine),
                    Contains("did you mean 'memory.l1.size'"));
  CHECK_THROWS_WITH(c.set("cores2", "4", ConfigSource::CommandLine),
                    Contains("did you mean 'cores'"));
  CHECK_THROWS_WITH(c.set("core", "4", ConfigSource::CommandLine),
                    Contains("core: '4' is not one of"));
  CHECK_THROWS_WITH(c.set("cores", "0", ConfigSource::CommandLine),
                    Contains("cores: 0 is out of range 1 .. 1024"));
  CHECK_THROWS_WITH(c.set("cores", "2.5", ConfigSource::CommandLine),
                    Contains("not a whole number"));
  CHECK_THROWS_WITH(c.set("scheduler", "lifo", ConfigSource::CommandLine), Contains("cfa|rr|fa"));
  CHECK_THROWS_WITH(c.setAssignment("cores", ConfigSource::CommandLine), Contains("key=value"));
  CHECK_THROWS_WITH(c.loadText("cores = 4\n[memory.l1]\nsise = 3\n", "toml", "'x.toml'",
                               ConfigSource::File),
                    Contains("'x.toml': unknown setting 'memory.l1.sise'"));
  CHECK_THROWS_WITH(c.loadText("cores = [", "toml", "'y.toml'", ConfigSource::File),
                    Contains("'y.toml'"));
}

TEST_CASE("TOML and JSON files, nested or dotted, give the same configuration", "[config]") {
  Configuration toml, json, dotted;
  toml.loadText("cores = 8\n[memory]\nkind = \"cached\"\n[memory.l1]\nsize = \"8KiB\"\nways = 2\n",
                "toml", "t", ConfigSource::File);
  json.loadText(R"({"cores": 8, "memory": {"kind": "cached", "l1": {"size": "8KiB", "ways": 2}}})",
                "json", "j", ConfigSource::File);
  dotted.loadText(
      R"({"cores": 8, "memory.kind": "cached", "memory.l1.size": 8192, "memory.l1.ways": 2})",
      "json", "d", ConfigSource::File);
  CHECK(toml.toJson() == json.toJson());
  CHECK(toml.toJson() == dotted.toJson());
  CHECK(toml.values().rtu.memory.l1.ways == 2);
}

TEST_CASE("config --dump loads again to the same configuration", "[config]") {
  Configuration original;
  original.applyPreset("cached");
  original.set("cores", "4", ConfigSource::CommandLine);
  original.set("scene.depth", "5", ConfigSource::CommandLine);  // beside the key `scene`
  original.set("camera.fov", "37.5", ConfigSource::CommandLine);
  original.set("job_manager.epsilon", "0.001", ConfigSource::CommandLine);
  Configuration loaded;
  loaded.loadText(original.toToml(), "toml", "dump", ConfigSource::File);
  CHECK(loaded.toJson() == original.toJson());
  CHECK(loaded.toToml() == original.toToml());
  Configuration fromJson;
  fromJson.loadText(original.toJson().dump(), "json", "dump", ConfigSource::File);
  CHECK(fromJson.toJson() == original.toJson());
}

TEST_CASE("Each flag names one setting, the two epsilons have their own (issue 26)", "[config]") {
  std::set<std::string> flags;
  for (const Setting& s : configSchema())
    if (!s.flag.empty()) CHECK(flags.insert(s.flag).second);
  for (const Setting& s : configSchema())
    if (!s.formerFlag.empty()) CHECK(flags.count(s.formerFlag) == 0);  // never today's flag
  CHECK(findSetting("job_manager.epsilon").flag == "--ray-epsilon");
  CHECK(findSetting("camera.epsilon").flag == "--camera-epsilon");
  CHECK(findSetting("job_manager.epsilon").formerFlag == "--epsilon");
  CHECK(findSetting("camera.epsilon").formerFlag == "--epsilon");
  // The ambiguous --epsilon keeps the first declared setting's meaning (schema_flags.cpp).
  const auto& schema = configSchema();
  const auto at = [&](const std::string& key) {
    return std::find_if(schema.begin(), schema.end(),
                        [&](const Setting& s) { return s.key == key; });
  };
  CHECK(at("job_manager.epsilon") < at("camera.epsilon"));
}

TEST_CASE("Every shipped preset loads and is a valid configuration", "[config]") {
  const std::vector<std::string> names = presetNames();
  CHECK(names == std::vector<std::string>{"asic", "cached", "fixedpoint", "thesis", "trayracer"});
  for (const std::string& name : names) {
    INFO(name);
    Configuration c;
    c.applyPreset(name);
    CHECK_NOTHROW(validate(c.values().rtu));
    CHECK_NOTHROW(c.values().raypipe.validate());
    // An RTU preset states its cores; the ray pipe's has none.
    const bool rtu = c.values().architecture == Architecture::Rtu;
    CHECK(c.source(rtu ? "cores" : "architecture") == ConfigSource::Preset);
  }
  Configuration thesis;
  thesis.applyPreset("thesis");
  CHECK(thesis.values().rtu.cores == 16);
  CHECK(thesis.values().rtu.memory.ideal);
  CHECK(thesis.values().rtu.clockMhz == 100.0);
  CHECK(thesis.values().rtu.hostInput.bytesPerCycle == 8.0);  // 64-bit AXI DMA, 4 cycles a ray
  CHECK_THROWS_WITH(thesis.applyPreset("fast"),
                    Contains("asic, cached, fixedpoint, thesis, trayracer"));
  // Seed 004's hardware: one BIH core at 233 MHz on ROM, the VHDL's formats, the 41-cycle unit.
  Configuration fixedpoint;
  fixedpoint.applyPreset("fixedpoint");
  const RtuConfig& rtu = fixedpoint.values().rtu;
  CHECK(rtu.core == "bih");
  CHECK(rtu.cores == 1);
  CHECK(rtu.memory.ideal);
  CHECK(rtu.clockMhz == 233.0);
  const BihConfig& bih = rtu.coreConfig<BihKind<>>();
  CHECK(bihFormatName(bih.format) == "vhdl");
  CHECK(bih.cycles.triangleLatency == 41);
  CHECK(bih.cycles.triangleInterval == 1);
  CHECK_FALSE(bih.earlyOut);
}

TEST_CASE("The trayracer preset is seed 001's final build at 640x480", "[config][raypipe]") {
  Configuration c;
  c.applyPreset("trayracer");
  const RunConfig& run = c.values();
  CHECK(run.architecture == Architecture::Raypipe);
  CHECK(run.raypipeView.level == 5);
  // R1 INIT_CAM (SYNTH): 0x3F900000 = 1.125, 0xBFA00000 = -1.25; U, V, W the unit axes.
  CHECK(run.raypipeView.camera.eye == std::array<float, 3>{1.125f, 1.125f, -1.25f});
  CHECK(run.raypipeView.camera.u == std::array<float, 3>{1, 0, 0});
  CHECK(run.raypipeView.camera.v == std::array<float, 3>{0, 1, 0});
  CHECK(run.raypipeView.camera.w == std::array<float, 3>{0, 0, 1});
  CHECK(run.raypipe.shortStackDepth == 4);
  CHECK(run.raypipe.raysInFlight == 512);
  CHECK(run.raypipe.clockMHz == 50.0);
  CHECK(run.raypipe.cache == RaypipeCacheKind::BlockRam);
  // Its dump loads back to the same configuration, the unset registers of another included.
  Configuration again;
  again.loadText(c.toToml(), "toml", "dump", ConfigSource::File);
  CHECK(again.toJson() == c.toJson());
  Configuration unset;
  unset.loadText(Configuration().toToml(), "toml", "dump", ConfigSource::File);
  CHECK_FALSE(unset.values().raypipeView.camera.eye.has_value());
}

TEST_CASE("Ray pipe settings and the RTU's report each other as having no effect",
          "[config][raypipe]") {
  Configuration rtu;
  rtu.set("raypipe.short_stack_depth", "2", ConfigSource::File);
  const std::string why = whyIneffective(findSetting("raypipe.short_stack_depth"), rtu.values(),
                                         kUseArithmetic, "render");
  CHECK(why == "architecture is rtu");
  Configuration pipe;
  pipe.set("architecture", "raypipe", ConfigSource::CommandLine);
  pipe.set("raypipe.level", "3", ConfigSource::CommandLine);
  CHECK(whyIneffective(findSetting("cores"), pipe.values(), kUseModel, "render") ==
        "architecture is raypipe");
  CHECK(whyIneffective(findSetting("width"), pipe.values(), kUseCamera, "render") ==
        "raypipe.level is 3");
  CHECK(whyIneffective(findSetting("raypipe.level"), pipe.values(), kUseCamera, "render").empty());
  CHECK_THROWS_WITH(pipe.set("raypipe.level", "6", ConfigSource::CommandLine),
                    Contains("raypipe.level"));
  CHECK_THROWS_WITH(pipe.set("raypipe.camera.w", "1,2", ConfigSource::CommandLine),
                    Contains("raypipe.camera.w"));
}

TEST_CASE("Settings a user gives that have no effect are reported", "[config]") {
  Configuration both;
  both.set("svo", "a.svo", ConfigSource::CommandLine);
  both.set("scene", "sphere", ConfigSource::CommandLine);
  CHECK_THROWS_WITH(both.checkApplicable(kUseScene, "render"),
                    Contains("scene (command line) has no effect: svo is given"));
  Configuration camera;
  camera.set("width", "64", ConfigSource::CommandLine);
  CHECK_THROWS_WITH(camera.checkApplicable(kUseBuffers | kUseModel, "replay"),
                    Contains("rtusim replay does not use it"));
  // Cache settings with ideal memory: a warning, so scripts with today's flags keep running.
  Configuration ideal;
  ideal.set("memory.l1.size", "1KiB", ConfigSource::CommandLine);
  CHECK_NOTHROW(ideal.checkApplicable(kUseModel, "replay"));
  // A preset's settings are never reported.
  Configuration preset;
  preset.applyPreset("cached");
  preset.set("memory.kind", "ideal", ConfigSource::CommandLine);
  CHECK_NOTHROW(preset.checkApplicable(kUseModel, "replay"));
}

TEST_CASE("A sweep is the product of its grids times its explicit list", "[config][sweep]") {
  Configuration base;
  base.set("width", "32", ConfigSource::CommandLine);
  SweepSpec spec;
  spec.addGrid("cores=1,2,4");
  spec.addGrid("memory.l1.size=1KiB,4KiB");
  const std::vector<Configuration> grid = allPoints(spec, base);
  REQUIRE(grid.size() == 6);
  CHECK(grid[0].values().rtu.cores == 1);
  CHECK(grid[0].values().rtu.memory.l1.sizeBytes == 1024);
  CHECK(grid[1].values().rtu.memory.l1.sizeBytes == 4096);
  CHECK(grid[5].values().rtu.cores == 4);
  CHECK(grid[5].values().camera.width == 32);
  spec.list = {{{"scheduler", "rr"}}, {{"scheduler", "fa"}, {"reorder", "4"}}};
  const std::vector<Configuration> both = allPoints(spec, base);
  REQUIRE(both.size() == 12);
  CHECK(both[0].values().rtu.scheduler == SchedulerPolicy::RoundRobin);
  CHECK(both[11].values().rtu.scheduler == SchedulerPolicy::FirstAvailable);
  CHECK(both[11].values().rtu.reorderCapacity == 4);
  CHECK_THROWS_WITH(spec.addGrid("coress=1,2"), Contains("did you mean 'cores'"));
  SweepSpec bad;
  bad.addGrid("cores=1,0");
  CHECK_THROWS_WITH(allPoints(bad, base), Contains("cores: 0 is out of range"));
}

TEST_CASE("A swept key without effect is refused before any row runs", "[config][sweep]") {
  constexpr unsigned sweepUses = kUseModel | kUseArithmetic | kUseScene | kUseCamera;
  SweepSpec latency;
  latency.addGrid("memory.dram.latency=10,20");
  CHECK_THROWS_WITH(
      checkSettingsHaveEffect(allPoints(latency, Configuration{}), sweepUses, "sweep"),
      Contains("memory.dram.latency (sweep) has no effect in any configuration: memory.kind is "
               "ideal"));
  Configuration cached;
  cached.set("memory.kind", "cached", ConfigSource::CommandLine);
  CHECK_NOTHROW(checkSettingsHaveEffect(allPoints(latency, cached), sweepUses, "sweep"));
  // Without effect in two of four configurations only: a warning.
  latency.addGrid("memory.kind=ideal,cached");
  CHECK_NOTHROW(checkSettingsHaveEffect(allPoints(latency, Configuration{}), sweepUses, "sweep"));
  // A list entry is checked in the configurations it sets.
  SweepSpec list;
  list.list = {{{"cores", "4"}}, {{"memory.l2.size", "64KiB"}}};
  CHECK_THROWS_WITH(checkSettingsHaveEffect(allPoints(list, Configuration{}), sweepUses, "sweep"),
                    Contains("memory.l2.size (sweep) has no effect in any configuration"));
  SweepSpec unused;
  unused.addGrid("width=8,16");
  CHECK_THROWS_WITH(checkSettingsHaveEffect(allPoints(unused, Configuration{}), kUseModel,
                                            "replay"),
                    Contains("width (sweep) has no effect in any configuration: rtusim replay "
                             "does not use it"));
}

TEST_CASE("A sweep judges the command line's keys over its rows", "[config][sweep]") {
  constexpr unsigned sweepUses = kUseModel | kUseArithmetic | kUseScene | kUseCamera | kUseAccel;
  // A BIH setting given with a sweep over `core`: the BIH rows use it (a warning for the others),
  // though the base configuration's SVO core does not.
  Configuration base;
  base.set("bih.triangle.latency", "20", ConfigSource::CommandLine);
  CHECK_FALSE(whyIneffective(findSetting("bih.triangle.latency"), base.values(), sweepUses, "sweep")
                  .empty());
  SweepSpec kinds;
  kinds.addGrid("core=svo,bih");
  CHECK_NOTHROW(checkSettingsHaveEffect(allPoints(kinds, base), sweepUses, "sweep"));
  // A command-line key the command does not use is refused as a single run refuses it.
  Configuration wide;
  wide.set("width", "64", ConfigSource::CommandLine);
  CHECK_THROWS_WITH(checkSettingsHaveEffect(allPoints(kinds, wide), kUseModel, "replay"),
                    Contains("width (command line) has no effect: rtusim replay does not use it"));
}

TEST_CASE("A statistics file is a configuration: its config object", "[config]") {
  Configuration rerun;
  rerun.loadText(R"({"rtusim": {"version": "x"}, "config": {"cores": 4, "memory.kind": "cached"},)"
                 R"( "statistics": {"rays": 64, "total_cycles": 1000}})",
                 "json", "'stats.json'", ConfigSource::File);
  CHECK(rerun.values().rtu.cores == 4);
  CHECK_FALSE(rerun.values().rtu.memory.ideal);
  CHECK(rerun.source("cores") == ConfigSource::File);
}

TEST_CASE("Numbers that would change value are refused\\, not read leniently", "[config]") {
  Configuration c;
  const auto set = [&c](const std::string& key, const std::string& text) {
    c.set(key, text, ConfigSource::CommandLine);
  };
  CHECK_THROWS_WITH(set("cores", "010"), Contains("cores: '010' has a leading zero"));
  CHECK_THROWS_WITH(set("cores", "0x4"), Contains("cores: '0x4' is not a decimal number"));
  // 2^53 + 1 read as a double is 2^53, inside scene.seed's range: it was silently rounded.
  CHECK_THROWS_WITH(set("scene.seed", "9007199254740993"),
                    Contains("'9007199254740993' is beyond 2^53"));
  set("scene.seed", "9007199254740992");
  CHECK(c.values().scene.seed == 9007199254740992ull);
  set("cores", "10");
  CHECK(c.values().rtu.cores == 10);
  // An array given to a setting of one value was read as its elements joined: [4] as 4.
  CHECK_THROWS_WITH(c.loadText("cores = [4]", "toml", "'c.toml'", ConfigSource::File),
                    "'c.toml': cores: an array is given where the setting takes one value");
  CHECK_THROWS_WITH(c.loadText("{\"cores\": [4]}", "json", "'c.json'", ConfigSource::File),
                    "'c.json': cores: an array is given where the setting takes one value");
  c.loadText("camera.up = [0, 0, 1]", "toml", "'c.toml'", ConfigSource::File);
  CHECK(c.values().camera.up.z == 1.0);
}

TEST_CASE("A sweep's points are computed from their index\\, none held", "[config][sweep]") {
  // 10^12 points (the grid was refused over the machine's memory when its points were held): made
  // at once, any point computed from its index, the last key fastest.
  SweepSpec spec;
  std::vector<std::string> values;
  for (int i = 1; i <= 1000; ++i) values.push_back(std::to_string(i));
  for (const char* key : {"cores", "width", "height", "clock_mhz"})
    spec.grid.emplace_back(key, values);
  const SweepPoints points(spec, Configuration{});
  REQUIRE(points.size() == 1000000000000u);
  const Configuration last = points.at(points.size() - 1);
  CHECK(last.values().rtu.cores == 1000);
  CHECK(last.values().camera.height == 1000);
  const Configuration some =
      points.at(((size_t{4} * 1000 + 999) * 1000 + 6) * 1000 + 7);  // 5, 1000, 7, 8
  CHECK(some.values().rtu.cores == 5);
  CHECK(some.values().camera.width == 1000);
  CHECK(some.values().camera.height == 7);
  CHECK(some.values().rtu.clockMhz == 8);
  CHECK(points.describe(1) == "cores=1 width=1 height=1 clock_mhz=2");
  // Through JSON (a Slurm plan), the same points.
  const SweepPoints back = SweepPoints::fromJson(points.toJson());
  REQUIRE(back.size() == points.size());
  CHECK(back.at(123456789).toJson() == points.at(123456789).toJson());
}

TEST_CASE("A sweep's points are distinct configurations", "[config][sweep]") {
  SweepSpec spec;
  spec.addGrid("cores=4,4,8");  // the same value: once
  spec.addGrid("width=16,32");
  spec.addGrid("width=64");  // set last: the earlier grid of width is overridden
  spec.list = {{{"scheduler", "rr"}}, {{"scheduler", "rr"}, {"width", "8"}}, {{"reorder", "4"}}};
  const SweepPoints points(spec, Configuration{});
  REQUIRE(points.size() == 4);  // 2 cores x 1 width x 2 entries (the second is the first)
  std::set<std::string> distinct;
  for (size_t i = 0; i < points.size(); ++i) {
    distinct.insert(points.at(i).toJson().dump());
    CHECK(points.at(i).values().camera.width == 64);
  }
  CHECK(distinct.size() == 4);
  CHECK(points.describe(3) == "reorder=4 cores=8 width=64");
}
