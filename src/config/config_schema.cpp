#include "config/config_schema.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "base/timing_limits.h"
#include "kinds/bih/bih_config.h"
#include "kinds/bvh/bvh_config.h"
#include "kinds/registry.h"
#include "kinds/svo/procedural_scenes.h"
#include "raypipe/primary_rays.h"

namespace rtu {
namespace {

// A field is a callable that selects a member: RunConfig& -> T&.
template <class F>
using FieldType = std::remove_reference_t<std::invoke_result_t<F, RunConfig&>>;

template <class F>
const FieldType<F>& read(const F& field, const RunConfig& config) {
  return field(const_cast<RunConfig&>(config));  // the field function only selects a member
}

[[noreturn]] void fail(const std::string& key, const std::string& message) {
  throw std::invalid_argument(key + ": " + message);
}

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// The shortest decimal text that reads back as the same value of type T (float or double).
template <class T = double>
std::string formatReal(T value) {
  char text[64];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(text, sizeof text, "%.*g", precision, static_cast<double>(value));
    if (static_cast<T>(std::strtod(text, nullptr)) == value) break;
  }
  return text;
}

// Integers are decimal and exact: "010" is not read as 10 (nor as octal 8), "0x10" not as 16, and
// a value beyond 2^53, where a double holds integers no longer exactly, is refused, not rounded
// (9007199254740993 became 9007199254740992).
void checkIntegerText(const std::string& value, double number, const std::string& key) {
  const size_t digits = value.find_first_not_of("+-");
  if (value.find_first_of("xX") != std::string::npos)
    fail(key, "'" + value + "' is not a decimal number");
  if (digits != std::string::npos && value[digits] == '0' && digits + 1 < value.size() &&
      std::isdigit(static_cast<unsigned char>(value[digits + 1])))
    fail(key, "'" + value + "' has a leading zero (octal is not read: write it without)");
  constexpr double kExactIntegers = 9007199254740992.0;  // 2^53
  const bool plain = value.find_first_not_of("+-0123456789") == std::string::npos;
  if (std::fabs(number) > kExactIntegers ||
      (plain && std::to_string(static_cast<long long>(number)) !=
                    std::to_string(std::strtoll(value.c_str(), nullptr, 10))))
    fail(key, "'" + value + "' is beyond 2^53, where it would be rounded");
}

double parseNumber(const std::string& text, const std::string& key, bool integer) {
  const std::string value = trim(text);
  size_t used = 0;
  double number = 0;
  try {
    number = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (value.empty() || used != value.size() || !std::isfinite(number))
    fail(key, "'" + text + "' is not a number");
  if (integer && number != std::floor(number)) fail(key, "'" + text + "' is not a whole number");
  if (integer) checkIntegerText(value, number, key);
  return number;
}

void checkRange(double value, const Setting& setting) {
  if (value == 0 && setting.zeroAllowed) return;
  if (value < setting.min || value > setting.max)
    fail(setting.key, formatReal(value) + " is out of range " + setting.range());
}

Setting declare(std::string key, std::string flag, SettingKind kind, std::string unit,
                unsigned uses, std::string doc) {
  Setting setting;
  setting.key = std::move(key);
  setting.flag = std::move(flag);
  setting.kind = kind;
  setting.unit = std::move(unit);
  setting.uses = uses;
  setting.doc = std::move(doc);
  return setting;
}

template <class F>
Setting number(SettingKind kind, std::string key, std::string flag, std::string unit, double min,
               double max, unsigned uses, std::string doc, F field, bool zeroAllowed = false) {
  using T = FieldType<F>;
  Setting s = declare(std::move(key), std::move(flag), kind, std::move(unit), uses, std::move(doc));
  s.min = min;
  s.max = max;
  s.zeroAllowed = zeroAllowed;
  s.get = [field, kind](const RunConfig& c) -> std::string {
    const T value = read(field, c);
    if (kind == SettingKind::Bytes) return formatBytes(static_cast<uint64_t>(value));
    if (kind == SettingKind::Integer) return std::to_string(static_cast<long long>(value));
    return formatReal<std::conditional_t<std::is_same_v<T, float>, float, double>>(value);
  };
  s.assign = [field, s](RunConfig& c, const std::string& text) {
    const double value = s.kind == SettingKind::Bytes
                             ? static_cast<double>(parseBytes(text, s.key))
                             : parseNumber(text, s.key, s.kind == SettingKind::Integer);
    checkRange(value, s);
    field(c) = static_cast<T>(value);
  };
  return s;
}

template <class F>
Setting integer(std::string key, std::string flag, std::string unit, double min, double max,
                unsigned uses, std::string doc, F field) {
  return number(SettingKind::Integer, std::move(key), std::move(flag), std::move(unit), min, max,
                uses, std::move(doc), field);
}

template <class F>
Setting real(std::string key, std::string flag, std::string unit, double min, double max,
             unsigned uses, std::string doc, F field) {
  return number(SettingKind::Real, std::move(key), std::move(flag), std::move(unit), min, max, uses,
                std::move(doc), field);
}

// A rate where 0 means unlimited.
template <class F>
Setting realOrZero(std::string key, std::string flag, std::string unit, double min, double max,
                   unsigned uses, std::string doc, F field) {
  return number(SettingKind::Real, std::move(key), std::move(flag), std::move(unit), min, max, uses,
                std::move(doc), field, /*zeroAllowed=*/true);
}

template <class F>
Setting bytes(std::string key, std::string flag, double max, unsigned uses, std::string doc,
              F field) {
  return number(SettingKind::Bytes, std::move(key), std::move(flag), "bytes", 1, max, uses,
                std::move(doc), field);
}

// An enumeration shown by name: `names` maps the stored value to text, `parse` back.
template <class F, class T = FieldType<F>>
Setting choice(std::string key, std::string flag, std::vector<std::string> choices, unsigned uses,
               std::string doc, F field, std::string (*name)(const T&),
               T (*parse)(const std::string&)) {
  Setting s =
      declare(std::move(key), std::move(flag), SettingKind::Choice, "", uses, std::move(doc));
  s.choices = std::move(choices);
  s.get = [field, name](const RunConfig& c) { return name(read(field, c)); };
  s.assign = [field, parse, s](RunConfig& c, const std::string& text) {
    const std::string value = trim(text);
    if (std::find(s.choices.begin(), s.choices.end(), value) == s.choices.end())
      fail(s.key, "'" + text + "' is not one of " + s.range());
    field(c) = parse(value);
  };
  return s;
}

template <class F>
Setting text(SettingKind kind, std::string key, std::string flag, unsigned uses, std::string doc,
             F field) {
  Setting s = declare(std::move(key), std::move(flag), kind, "", uses, std::move(doc));
  s.get = [field](const RunConfig& c) { return read(field, c); };
  s.assign = [field](RunConfig& c, const std::string& value) { field(c) = value; };
  return s;
}

template <class F>
Setting flag(std::string key, std::string flagName, unsigned uses, std::string doc, F field) {
  Setting s =
      declare(std::move(key), std::move(flagName), SettingKind::Flag, "", uses, std::move(doc));
  s.get = [field](const RunConfig& c) { return std::string(read(field, c) ? "true" : "false"); };
  s.assign = [field, key = s.key](RunConfig& c, const std::string& text) {
    const std::string value = trim(text);
    if (value == "true" || value == "1")
      field(c) = true;
    else if (value == "false" || value == "0")
      field(c) = false;
    else
      fail(key, "'" + text + "' is not true or false");
  };
  return s;
}

template <class F>
Setting vector(std::string key, std::string flagName, unsigned uses, std::string doc, F field) {
  Setting s =
      declare(std::move(key), std::move(flagName), SettingKind::Vector, "", uses, std::move(doc));
  s.get = [field](const RunConfig& c) {
    const glm::dvec3& v = read(field, c);
    return formatReal(v.x) + "," + formatReal(v.y) + "," + formatReal(v.z);
  };
  s.assign = [field, key = s.key](RunConfig& c, const std::string& value) {
    field(c) = parseVector(value, key);
  };
  return s;
}

// Enumerations by name.
std::string schedulerName(const SchedulerPolicy& p) { return toString(p); }
std::string replacementName(const Replacement& r) { return toString(r); }
std::string conversionName(const FloatConversion& c) { return toString(c); }
std::string memoryKindName(const bool& ideal) { return ideal ? "ideal" : "cached"; }
bool parseMemoryKind(const std::string& name) { return name == "ideal"; }
// Choices stored as their own text (scene names, core kinds).
std::string sameText(const std::string& text) { return text; }

std::string ignoredWithIdealMemory(const RunConfig& c) {
  return c.rtu.memory.ideal ? "memory.kind is ideal" : "";
}
std::string ignoredWithSceneFile(const RunConfig& c) {
  if (!c.scene.svoFile.empty()) return "svo is given";
  if (!c.scene.meshFile.empty()) return "mesh is given";
  if (!c.scene.binvoxFile.empty()) return "binvox is given";
  return "";
}
std::string ignoredWithoutBuiltTree(const RunConfig& c) {
  if (!c.scene.svoFile.empty()) return "svo is given";
  if (!c.scene.binvoxFile.empty()) return "binvox is given";
  if (!c.scene.meshFile.empty() && c.accel.structure != "svo")
    return "mesh is given and accel is " + c.accel.structure;
  return "";
}

std::string modelKindName(const ModelKind& model) { return toString(model); }

// A structure's settings act when `build --accel` builds it or a run's core kind of its name does.
std::function<std::string(const RunConfig&)> ignoredUnlessBuilt(const std::string& structure) {
  return [structure](const RunConfig& c) {
    return c.accel.structure == structure || c.rtu.core == structure
               ? std::string()
               : "accel is " + c.accel.structure + " and the core kind is " + c.rtu.core;
  };
}

// The k-d tree's build settings count for a kdtree build, the k-d core and the ray pipe.
std::string ignoredUnlessKd(const RunConfig& c) {
  return c.accel.structure == "kdtree" || c.rtu.core == "kd" ||
                 c.architecture == Architecture::Raypipe
             ? std::string()
             : "accel is " + c.accel.structure + " and the core kind is " + c.rtu.core;
}

// What `build` makes: the structure, then each triangle structure's own settings.
void addAccelSettings(std::vector<Setting>& schema) {
  using C = RunConfig;
  schema.push_back(choice(
      "accel", "--accel", {"svo", "bvh", "bih", "kdtree"}, kUseAccel,
      "the structure to build: svo (the thesis' octree), bvh (seed 003), bih (seed 004) or kdtree "
      "(seed 001) over the scene's triangles (a voxel scene's faces)",
      [](C& c) -> std::string& { return c.accel.structure; }, sameText, sameText));
  schema.push_back(choice(
      "accel.builder", "--builder", {"langr", "binned", "sweep", "lbvh"}, kUseAccel,
      "BVH builder: langr (seed 003's Algorithms 3-4), binned (SAH, 32 bins), sweep (full-sweep "
      "SAH) or lbvh (Morton codes)",
      [](C& c) -> std::string& { return c.accel.builder; }, sameText, sameText));
  schema.back().ignoredBecause = ignoredUnlessBuilt("bvh");
  schema.push_back(flag("accel.drop_bad_triangles", "--drop-bad-triangles", kUseAccel,
                        "drop degenerate and duplicate triangles instead of refusing the mesh",
                        [](C& c) -> bool& { return c.accel.dropBadTriangles; }));
  schema.back().ignoredBecause = [](const C& c) {
    return c.accel.structure == "svo" && c.rtu.core == "svo" && c.architecture == Architecture::Rtu
               ? std::string("accel is svo and the core kind is svo")
               : std::string();
  };
  schema.push_back(choice(
      "accel.bih_format", "--bih-format", {"c99", "vhdl"}, kUseAccel,
      "BIH number formats: seed 004's C99 listing (n = 29) or its VHDL (n = 30)",
      [](C& c) -> FixedTriangleFormat& { return c.rtu.coreConfig<BihKind<>>().format; },
      bihFormatName, parseBihFormat));
  schema.back().ignoredBecause = ignoredUnlessBuilt("bih");
  schema.push_back(choice(
      "accel.index", "--index", {"seed", "wide"}, kUseAccel,
      "index widths: the seed's (BIH: 10-bit node indices; k-d tree: the Tray Racer's 48-bit "
      "nodes and 16-bit ids) or wide (BIH: 29 bits; k-d tree: the file's wide variant)",
      [](C& c) -> std::string& { return c.accel.index; }, sameText, sameText));
  schema.back().ignoredBecause = [](const C& c) {
    const std::string bih = ignoredUnlessBuilt("bih")(c);
    // The ray pipe's k-d tree takes it too (the scene file's narrow or wide form).
    return bih.empty() || c.accel.structure == "kdtree" || c.architecture == Architecture::Raypipe
               ? std::string()
               : bih;
  };
  schema.push_back(choice(
      "accel.kd_edge_order", "--kd-edge-order", {"flat", "pbrt", "r1"}, kUseAccel,
      "k-d tree: the order of edges at equal positions: flat (R1's, but a triangle flat on the "
      "axis between the others' ENDs and STARTs, so it is kept), pbrt (PBRT v1's, a START first: "
      "kept too, but a triangle touching the plane goes to both sides) or r1 (the Tray Racer "
      "team's, an END first, which drops a triangle flat in the split plane; their files)",
      [](C& c) -> std::string& { return c.accel.kdEdgeOrder; }, sameText, sameText));
  schema.back().ignoredBecause = ignoredUnlessKd;
  schema.push_back(choice(
      "accel.kd_matrix", "--kd-matrix", {"normal", "r1"}, kUseAccel,
      "k-d tree: the unit-triangle matrices' third column: normal (N itself, never singular) or "
      "r1 (R1's N - C, as the seed's files: singular for a triangle whose plane lies at distance "
      "1 from the origin, which is then never hit)",
      [](C& c) -> std::string& { return c.accel.kdMatrix; }, sameText, sameText));
  schema.back().ignoredBecause = ignoredUnlessKd;
  schema.push_back(text(SettingKind::Path, "accel_file", "--accel-file", kUseBuffers,
                        "a triangle structure's memory image (.bvh) to trace ray records through",
                        [](C& c) -> std::string& { return c.accel.file; }));
}

std::string ignoredUnlessLooselyTimed(const RunConfig& c) {
  return c.model == ModelKind::LooselyTimed ? "" : std::string("model is ") + toString(c.model);
}

std::string ignoredWithoutSampling(const RunConfig& c) {
  return c.sample.enabled() ? "" : "sample.fraction is 0 (every ray simulated)";
}

// The six settings of one cache level; `level` selects its configuration.
void addCache(std::vector<Setting>& schema, const std::string& level,
              CacheConfig& (*cache)(RunConfig&)) {
  using C = RunConfig;
  const std::string key = "memory." + level + ".";
  const std::string flag = "--" + level + "-";
  const std::string name = level == "l1" ? "L1" : "L2";
  std::vector<Setting> added;
  added.push_back(bytes(key + "size", flag + "size", 1u << 30, kUseModel, name + " size",
                        [cache](C& c) -> uint32_t& { return cache(c).sizeBytes; }));
  added.push_back(bytes(key + "line", flag + "line", 1u << 16, kUseModel, name + " line size",
                        [cache](C& c) -> uint32_t& { return cache(c).lineBytes; }));
  added.push_back(integer(key + "ways", flag + "ways", "", 1, 1024, kUseModel,
                          name + " associativity",
                          [cache](C& c) -> uint32_t& { return cache(c).ways; }));
  added.push_back(choice(
      key + "replacement", flag + "replacement", {"lru", "fifo", "random"}, kUseModel,
      name + " replacement policy", [cache](C& c) -> Replacement& { return cache(c).replacement; },
      replacementName, parseReplacement));
  added.push_back(integer(key + "latency", flag + "latency", "cycles", 0, kMaxLatencyCycles,
                          kUseModel, name + " hit latency",
                          [cache](C& c) -> uint32_t& { return cache(c).hitLatency; }));
  added.push_back(integer(key + "mshrs", flag + "mshrs", "", 1, 4096, kUseModel,
                          name + " outstanding-miss limit",
                          [cache](C& c) -> uint32_t& { return cache(c).maxOutstandingMisses; }));
  for (Setting& s : added) {
    s.ignoredBecause = ignoredWithIdealMemory;
    schema.push_back(std::move(s));
  }
}

// The SVO kind's settings (kinds/svo, RtuConfig::coreConfig<SvoKind>()): its stack and number
// format. With another kind of core they have no effect.
void addSvoSettings(std::vector<Setting>& schema) {
  constexpr unsigned arith = kUseArithmetic;
  std::vector<Setting> added;
  added.push_back(integer("stack_frames", "--stack-frames", "frames", 1, kMaxStackFrames, arith,
                          "traversal stack depth (RTL: 11)", [](RunConfig& c) -> int& {
                            return c.rtu.coreConfig<SvoKind>().stackFrames;
                          }));
  added.push_back(flag("allow_stack_overflow", "--allow-stack-overflow", arith,
                       "run even when a tree is deeper than the stack (such rays are flagged)",
                       [](RunConfig& c) -> bool& { return c.allowStackOverflow; }));
  added.push_back(
      integer("format.total_bits", "--total-bits", "bits", 8, 48, arith, "fixed-point word width",
              [](RunConfig& c) -> int& { return c.rtu.coreConfig<SvoKind>().format.totalBits; }));
  added.push_back(integer("format.fraction_bits", "--fraction-bits", "bits", 1, 46, arith,
                          "fixed-point fraction bits", [](RunConfig& c) -> int& {
                            return c.rtu.coreConfig<SvoKind>().format.fractionBits;
                          }));
  added.push_back(choice(
      "format.conversion", "--conversion", {"rtl", "exact"}, arith,
      "float-to-fixed conversion: rtl (as the hardware computes it) or exact",
      [](RunConfig& c) -> FloatConversion& { return c.rtu.coreConfig<SvoKind>().conversion; },
      conversionName, parseFloatConversion));
  for (Setting& s : added) {
    s.ignoredBecause = [](const RunConfig& c) {
      return c.rtu.core == SvoKind::kName ? std::string() : "the core kind is " + c.rtu.core;
    };
    schema.push_back(std::move(s));
  }
}

std::string triangleTestName(const TriangleTest& test) { return toString(test); }
std::string childOrderName(const ChildOrder& order) { return toString(order); }

// Why a setting of the kinds named `kinds` has no effect in `c`, or empty when it has one.
std::function<std::string(const RunConfig&)> ignoredUnlessCore(std::vector<std::string> kinds) {
  return [kinds](const RunConfig& c) {
    return std::find(kinds.begin(), kinds.end(), c.rtu.core) != kinds.end()
               ? std::string()
               : "the core kind is " + c.rtu.core;
  };
}

// A unit's cycles that the BVH and k-d cores share (kinds/bvh/bvh_timing.h, kinds/kd/kd_timing.h):
// one key writes both kinds' settings, and reads the chosen kind's.
Setting sharedUnitCycles(std::string key, std::string flag, std::string doc,
                         uint32_t BvhCycles::*bvh, uint32_t KdCycles::*kd) {
  using C = RunConfig;
  Setting s =
      integer(key, flag, "cycles", 1, kMaxBvhUnitCycles, kUseArithmetic, doc,
              [bvh](C& c) -> uint32_t& { return c.rtu.coreConfig<BvhKind<>>().cycles.*bvh; });
  const Setting kdView =
      integer(key, flag, "cycles", 1, kMaxKdUnitCycles, kUseArithmetic, doc,
              [kd](C& c) -> uint32_t& { return c.rtu.coreConfig<KdKind>().cycles.*kd; });
  s.get = [bvhGet = s.get, kdGet = kdView.get](const C& c) {
    return c.rtu.core == KdKind::kName ? kdGet(c) : bvhGet(c);
  };
  s.assign = [bvhAssign = s.assign, kdAssign = kdView.assign](C& c, const std::string& text) {
    bvhAssign(c, text);
    kdAssign(c, text);
  };
  s.ignoredBecause = ignoredUnlessCore({BvhKind<>::kName, KdKind::kName});
  return s;
}

// The BVH kind's settings (kinds/bvh, RtuConfig::coreConfig<BvhKind<>>()): its stack, child
// order, triangle test and units' cycles (kinds/bvh/bvh_timing.h; shared with the k-d core), all
// arithmetic: the cycles are in the golden traversal's costs too. With another kind of core they
// have no effect; the triangle test also chooses the golden run's over an accel_file.
void addBvhSettings(std::vector<Setting>& schema) {
  using C = RunConfig;
  constexpr unsigned arith = kUseArithmetic;
  std::vector<Setting> added;
  added.push_back(integer("core.stack_depth", "--stack-depth", "entries", 1, kMaxBvhStackDepth,
                          arith,
                          "BVH traversal stack entries (a push onto a full stack drops "
                          "the oldest, counted as bvh_stack_overflows)",
                          [](C& c) -> int& { return c.rtu.coreConfig<BvhKind<>>().stackDepth; }));
  added.push_back(choice(
      "core.child_order", "--child-order", {"entry", "axis"}, arith,
      "BVH: which of two hit children goes first: entry (the nearer entry) or axis (the ray's "
      "sign on the axis separating them)",
      [](C& c) -> ChildOrder& { return c.rtu.coreConfig<BvhKind<>>().childOrder; }, childOrderName,
      parseChildOrder));
  for (Setting& s : added) {
    s.ignoredBecause = ignoredUnlessCore({BvhKind<>::kName});
    schema.push_back(std::move(s));
  }
  schema.push_back(sharedUnitCycles(
      "core.box.latency", "--box-latency",
      "BVH: cycles of a node's box tests (both children at once); k-d: SINT's scene box test and "
      "TRAV's plane test",
      &BvhCycles::boxLatency, &KdCycles::boxLatency));
  schema.push_back(sharedUnitCycles(
      "core.triangle.latency", "--triangle-latency",
      "BVH and k-d: cycles from a ray/triangle test's issue to its result (a leaf's last test "
      "waits them)",
      &BvhCycles::triangleLatency, &KdCycles::triangleLatency));
  schema.push_back(sharedUnitCycles(
      "core.triangle.interval", "--triangle-interval",
      "BVH and k-d: the triangle unit's initiation interval, cycles between two tests' issues",
      &BvhCycles::triangleInterval, &KdCycles::triangleInterval));
  schema.push_back(integer(
      "core.transform.latency", "--transform-latency", "cycles", 1, kMaxBvhUnitCycles,
      kUseArithmetic,
      "BVH: cycles of XFORM, a two-level BVH's move of the ray into an instance's mesh space "
      "(animate --core bvh)",
      [](C& c) -> uint32_t& { return c.rtu.coreConfig<BvhKind<>>().cycles.transformLatency; }));
  schema.back().ignoredBecause = ignoredUnlessCore({BvhKind<>::kName});
  schema.push_back(integer(
      "core.triangle.shared_by", "--triangle-shared-by", "cores", 1, kMaxCores, kUseModel,
      "BVH, BIH and k-d: cores sharing one ray/triangle unit, round-robin (1: a unit per core; "
      "at most the core count)",
      [](C& c) -> int& { return c.rtu.triangleSharedBy; }));
  schema.back().ignoredBecause =
      ignoredUnlessCore({BvhKind<>::kName, BihKind<>::kName, KdKind::kName});
  schema.push_back(choice(
      "accel.triangle_test", "--triangle-test", {"watertight", "moller-trumbore"}, arith,
      "the BVH core's ray/triangle test in float32 (and the golden run's over an accel_file)",
      [](C& c) -> TriangleTest& { return c.rtu.coreConfig<BvhKind<>>().triangleTest; },
      triangleTestName, parseTriangleTest));
  schema.back().ignoredBecause = [](const C& c) {
    return c.rtu.core == BvhKind<>::kName || !c.accel.file.empty()
               ? std::string()
               : "the core kind is " + c.rtu.core + " and no triangle image (accel_file) is given";
  };
}

// The BIH kind's settings (kinds/bih, RtuConfig::coreConfig<BihKind<>>()): its triangle unit's
// cycles (kinds/bih/bih_timing.h) and the early-out option, arithmetic as the BVH's. Their own
// `bih.` keys: a key writes one kind's settings, and the BIH's unit has other defaults (the
// seed's 41 cycles) than the BVH's `core.triangle.*`. With another kind of core they have no
// effect.
void addBihSettings(std::vector<Setting>& schema) {
  using C = RunConfig;
  constexpr unsigned arith = kUseArithmetic;
  std::vector<Setting> added;
  added.push_back(integer(
      "bih.triangle.latency", "--bih-triangle-latency", "cycles", 1, kMaxBihUnitCycles, arith,
      "BIH: cycles from a ray/triangle test's issue to its result (seed 004: 41); a ray ends no "
      "earlier than its last test's result",
      [](C& c) -> uint32_t& { return c.rtu.coreConfig<BihKind<>>().cycles.triangleLatency; }));
  added.push_back(integer(
      "bih.triangle.interval", "--bih-triangle-interval", "cycles", 1, kMaxBihUnitCycles, arith,
      "BIH: the triangle unit's initiation interval, cycles between two tests' issues (seed 004: "
      "1)",
      [](C& c) -> uint32_t& { return c.rtu.coreConfig<BihKind<>>().cycles.triangleInterval; }));
  added.push_back(flag("bih.early_out", "--bih-early-out", arith,
                       "BIH: drop a popped node that begins beyond the nearest hit so far (not in "
                       "seed 004, S4 L577)",
                       [](C& c) -> bool& { return c.rtu.coreConfig<BihKind<>>().earlyOut; }));
  for (Setting& s : added) {
    s.ignoredBecause = [](const RunConfig& c) {
      return c.rtu.core == BihKind<>::kName ? std::string() : "the core kind is " + c.rtu.core;
    };
    schema.push_back(std::move(s));
  }
}

// The k-d kind's own setting (kinds/kd, RtuConfig::coreConfig<KdKind>()): its short stack, as
// seed 001's, with the restart; its units' cycles are the BVH's keys (sharedUnitCycles). With
// another kind of core it has no effect.
void addKdSettings(std::vector<Setting>& schema) {
  schema.push_back(integer(
      "core.short_stack", "--short-stack", "entries", 1, kMaxKdShortStack, kUseArithmetic,
      "k-d: short-stack entries (seed 001: 4); a push onto a full stack drops the oldest and a "
      "ray restarts at its restart node when the stack runs empty",
      [](RunConfig& c) -> int& { return c.rtu.coreConfig<KdKind>().stackDepth; }));
  schema.back().ignoredBecause = ignoredUnlessCore({KdKind::kName});
}

std::string architectureName(const Architecture& a) {
  return a == Architecture::Raypipe ? "raypipe" : "rtu";
}
Architecture parseArchitecture(const std::string& name) {
  return name == "raypipe" ? Architecture::Raypipe : Architecture::Rtu;
}
std::string raypipeCacheName(const RaypipeCacheKind& c) {
  return c == RaypipeCacheKind::SetAssociative ? "set_associative" : "block_ram";
}
RaypipeCacheKind parseRaypipeCache(const std::string& name) {
  return name == "set_associative" ? RaypipeCacheKind::SetAssociative : RaypipeCacheKind::BlockRam;
}
std::string divisionName(const Division& d) {
  return d == Division::TowardZero ? "toward_zero" : d == Division::Altfp ? "altfp_div" : "ieee";
}
Division parseDivision(const std::string& name) {
  if (name == "altfp_div") return Division::Altfp;
  return name == "toward_zero" ? Division::TowardZero : Division::Ieee;
}
std::string tMaxClampName(const KdTMaxClamp& c) {
  return c == KdTMaxClamp::Intended ? "intended" : "as_built";
}
KdTMaxClamp parseTMaxClamp(const std::string& name) {
  return name == "intended" ? KdTMaxClamp::Intended : KdTMaxClamp::AsBuilt;
}

// A camera register of the ray pipe: three binary32 values in hardware space, or unset (empty
// text), when rtusim's camera gives it.
template <class F>
Setting cameraRegister(std::string key, std::string doc, F field) {
  Setting s = declare(std::move(key), "", SettingKind::Vector, "", kUseCamera, std::move(doc));
  s.get = [field](const RunConfig& c) -> std::string {
    const auto& value = read(field, c);
    if (!value) return "";
    return formatReal<float>((*value)[0]) + "," + formatReal<float>((*value)[1]) + "," +
           formatReal<float>((*value)[2]);
  };
  s.assign = [field, key = s.key](RunConfig& c, const std::string& text) {
    if (trim(text).empty()) {
      field(c).reset();
      return;
    }
    const glm::dvec3 v = parseVector(text, key);
    const std::array<float, 3> value{static_cast<float>(v.x), static_cast<float>(v.y),
                                     static_cast<float>(v.z)};
    for (float x : value)
      if (!std::isfinite(x)) fail(key, "'" + text + "' is beyond binary32's range");
    field(c) = value;
  };
  return s;
}

// A frame's passes and how its secondary rays are spawned (issue 32, docs/workloads.md).
std::string orderName(const RayOrder& order) { return toString(order); }

std::string lightText(const Light& light) {
  const auto vector = [](const glm::dvec3& v) {
    return formatReal(v.x) + "," + formatReal(v.y) + "," + formatReal(v.z);
  };
  switch (light.shape) {
    case Light::Shape::Point: return vector(light.position);
    case Light::Shape::Rectangle:
      return std::string("rect:") + vector(light.position) + ":" + vector(light.edgeU) + ":" +
             vector(light.edgeV);
    case Light::Shape::Disc: break;
  }
  return std::string("disc:") + vector(light.position) + ":" + vector(light.normal) + ":" +
         formatReal(light.radius);
}

std::string lightsText(const std::vector<Light>& lights) {
  std::string text;
  for (const Light& light : lights) text += (text.empty() ? "" : ";") + lightText(light);
  return text;
}

std::vector<Light> parseLights(const std::string& text, const std::string& key) {
  std::vector<Light> lights;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(';', start), text.size());
    lights.push_back(parseLight(trim(text.substr(start, end - start)), key));
    start = end + 1;
  }
  return lights;
}

void addWorkloadSettings(std::vector<Setting>& s) {
  using C = RunConfig;
  constexpr unsigned workload = kUseWorkload;
  Setting passes = text(SettingKind::Text, "workload.rays", "--passes", workload,
                        "the frame's passes: primary, then any of shadow, ao, reflection, "
                        "diffuse, random spawned from its hits, run as one job stream in that "
                        "order, each pass's statistics its window of the run (',' or '+' "
                        "between them); shadow and ao shade render's image (docs/workloads.md)",
                        [](C& c) -> std::string& { return c.rayPasses; });
  passes.assign = [key = passes.key](C& c, const std::string& value) {
    parseRayPasses(trim(value), key);
    c.rayPasses = trim(value);
  };
  s.push_back(passes);
  Setting lights = declare("workload.lights", "--light", SettingKind::Text, "", workload,
                           "shadow rays' lights in world space, ';' between lights: a point "
                           "x,y,z, a rectangle rect:cx,cy,cz:ux,uy,uz:vx,vy,vz (centre, edges) "
                           "or a disc disc:cx,cy,cz:nx,ny,nz:r (centre, axis, radius), sampled "
                           "workload.light_samples times a hit (the default, a point, lies along "
                           "the shaded image's light, five units out)");
  lights.get = [](const C& c) { return lightsText(c.workload.secondary.lights); };
  lights.assign = [key = lights.key](C& c, const std::string& value) {
    c.workload.secondary.lights = parseLights(trim(value), key);
  };
  s.push_back(lights);
  s.push_back(integer("workload.light_samples", "--light-samples", "", 1, 1024, workload,
                      "shadow rays per primary hit to each area light (a point light takes one)",
                      [](C& c) -> int& { return c.workload.secondary.lightSamples; }));
  s.push_back(integer("workload.samples", "--samples", "", 1, 1024, workload,
                      "ao and diffuse rays per primary hit",
                      [](C& c) -> int& { return c.workload.secondary.samples; }));
  s.push_back(real("workload.ao_distance", "--ao-distance", "world units", 1e-9, 1e9, workload,
                   "the ao rays' length",
                   [](C& c) -> double& { return c.workload.secondary.aoDistance; }));
  s.push_back(integer("workload.random_rays", "--random-rays", "rays", 0, kMaxRayId + 1.0, workload,
                      "random: how many rays (0: one per pixel)",
                      [](C& c) -> size_t& { return c.workload.randomRays; }));
  s.push_back(integer("workload.seed", "--ray-seed", "", 0, 9007199254740992.0, workload,
                      "seed of the sampled directions, random rays and the shuffled order",
                      [](C& c) -> uint64_t& { return c.workload.secondary.seed; }));
  s.push_back(choice(
      "workload.order", "--order", {"pixel", "shuffled", "sorted"}, workload,
      "secondary rays' order: pixel (as spawned), shuffled (a wavefront "
      "renderer's), sorted (direction octant, then origin on a Morton curve)",
      [](C& c) -> RayOrder& { return c.workload.order; }, orderName, parseRayOrder));
}

// The ray pipe's settings (raypipe/raypipe_config.h, RunConfig::raypipe) and workload (its camera
// registers and resolution level): with architecture rtu they have no effect. Their keys are the
// ones RaypipeConfig::validate names.
void addRaypipeSettings(std::vector<Setting>& schema) {
  using C = RunConfig;
  constexpr unsigned model = kUseModel, arith = kUseArithmetic, camera = kUseCamera;
  constexpr double kMaxFifo = 1 << 20;
  std::vector<Setting> added;
  added.push_back(integer("raypipe.traversal_units", "", "units", 1, 2, model,
                          "ray pipe: traversal units (seed 001's final build: 1; its "
                          "raypipe_2trav.sv: 2)",
                          [](C& c) -> int& { return c.raypipe.traversalUnits; }));
  added.push_back(integer("raypipe.short_stack_depth", "--short-stack-depth", "entries", 1, 7,
                          arith,
                          "ray pipe: short-stack entries per ray (seed 001: 4; a push onto a full "
                          "stack overwrites the oldest)",
                          [](C& c) -> int& { return c.raypipe.shortStackDepth; }));
  added.push_back(integer("raypipe.rays_in_flight", "", "rays", 1, 512, model,
                          "ray pipe: ray ids the shader hands out (seed 001: 512, the 9-bit rayID)",
                          [](C& c) -> int& { return c.raypipe.raysInFlight; }));
  const std::pair<const char*, int& (*)(C&)> latencies[] = {
      {"prg", [](C& c) -> int& { return c.raypipe.latency.prg; }},
      {"prg_interval", [](C& c) -> int& { return c.raypipe.latency.prgInterval; }},
      {"sint", [](C& c) -> int& { return c.raypipe.latency.sint; }},
      {"sint_interval", [](C& c) -> int& { return c.raypipe.latency.sintInterval; }},
      {"trav_math", [](C& c) -> int& { return c.raypipe.latency.travMath; }},
      {"intersection", [](C& c) -> int& { return c.raypipe.latency.intersection; }},
      {"memory_read", [](C& c) -> int& { return c.raypipe.latency.memoryRead; }},
  };
  for (const auto& [name, field] : latencies)
    added.push_back(integer(
        std::string("raypipe.latency.") + name, "", "cycles", 1, kMaxLatencyCycles, model,
        std::string("ray pipe: ") + name + " cycles (an _interval: cycles between accepted items)",
        field));
  const std::pair<const char*, int& (*)(C&)> fifos[] = {
      {"prg", [](C& c) -> int& { return c.raypipe.fifo.prg; }},
      {"sint", [](C& c) -> int& { return c.raypipe.fifo.sint; }},
      {"tarb", [](C& c) -> int& { return c.raypipe.fifo.tarb; }},
      {"larb", [](C& c) -> int& { return c.raypipe.fifo.larb; }},
      {"trav_leaf", [](C& c) -> int& { return c.raypipe.fifo.travLeaf; }},
      {"trav_math", [](C& c) -> int& { return c.raypipe.fifo.travMath; }},
      {"int_list", [](C& c) -> int& { return c.raypipe.fifo.intList; }},
      {"int_larb", [](C& c) -> int& { return c.raypipe.fifo.intLarb; }},
      {"int_shader", [](C& c) -> int& { return c.raypipe.fifo.intShader; }},
      {"memory_out", [](C& c) -> int& { return c.raypipe.fifo.memoryOut; }},
      {"pixel_buffer", [](C& c) -> int& { return c.raypipe.fifo.pixelBuffer; }},
  };
  for (const auto& [name, field] : fifos)
    added.push_back(integer(std::string("raypipe.fifo.") + name, "", "entries", 1, kMaxFifo, model,
                            std::string("ray pipe: depth of the ") + name + " FIFO", field));
  added.push_back(choice(
      "raypipe.cache", "", {"block_ram", "set_associative"}, model,
      "ray pipe: block_ram (as built: full capacity, never a miss) or set_associative (the "
      "designed 2-way caches in front of DRAM: raypipe.cache_lines.*, raypipe.dram.*)",
      [](C& c) -> RaypipeCacheKind& { return c.raypipe.cache; }, raypipeCacheName,
      parseRaypipeCache));
  const std::pair<const char*, int& (*)(C&)> cacheLines[] = {
      {"tcache", [](C& c) -> int& { return c.raypipe.caches.tcacheLines; }},
      {"lcache", [](C& c) -> int& { return c.raypipe.caches.lcacheLines; }},
      {"icache", [](C& c) -> int& { return c.raypipe.caches.icacheLines; }},
  };
  for (const auto& [name, field] : cacheLines)
    added.push_back(integer(std::string("raypipe.cache_lines.") + name, "", "lines", 1, 1 << 20,
                            model,
                            std::string("ray pipe, set_associative: lines per way of the ") + name +
                                " (a power of two; the RTL's NUM_LINES)",
                            field));
  added.push_back(integer("raypipe.dram.latency", "", "cycles", 1, kMaxLatencyCycles, model,
                          "ray pipe, set_associative: cycles from the memory arbiter's read to "
                          "the DRAM's first word",
                          [](C& c) -> int& { return c.raypipe.caches.dramLatency; }));
  added.push_back(real("raypipe.dram.bytes_per_cycle", "", "bytes", 1e-3, 1e6, model,
                       "ray pipe, set_associative: the DRAM's bytes per cycle (the seed's "
                       "32-bit SDRAM: 4)",
                       [](C& c) -> double& { return c.raypipe.caches.dramBytesPerCycle; }));
  added.push_back(choice(
      "raypipe.division", "", {"ieee", "toward_zero", "altfp_div"}, arith,
      "ray pipe: the divider, ieee (correctly rounded), altfp_div (the shipped divider's "
      "algorithm, bit for bit) or toward_zero (bounds altfp_div's one-ulp errors)",
      [](C& c) -> Division& { return c.raypipe.division; }, divisionName, parseDivision));
  added.push_back(choice(
      "raypipe.tmax_clamp", "", {"as_built", "intended"}, arith,
      "ray pipe: the scene box's t_max, as_built (the RTL's: at least 1) or intended (the box's "
      "exit)",
      [](C& c) -> KdTMaxClamp& { return c.raypipe.tMaxClamp; }, tMaxClampName, parseTMaxClamp));
  added.push_back(flag("raypipe.vga_window", "", model,
                       "ray pipe: the pixel buffer's SRAM writer waits out the VGA reader, as "
                       "built (false: it takes a pixel every cycle)",
                       [](C& c) -> bool& { return c.raypipe.vgaWindow; }));
  added.push_back(integer("raypipe.vga_phase", "", "cycles", 0, 833599, model,
                          "ray pipe: cycles from reset to the frame's start, which place the VGA "
                          "reader's screen (a screen is 833,600 cycles)",
                          [](C& c) -> int64_t& { return c.raypipe.vgaPhase; }));
  added.push_back(real("raypipe.clock_mhz", "", "MHz", kMinClockMhz, kMaxClockMhz, model,
                       "ray pipe: clock (seed 001: 50 MHz)",
                       [](C& c) -> double& { return c.raypipe.clockMHz; }));
  const std::pair<const char*, std::optional<std::array<float, 3>>& (*)(C&)> registers[] = {
      {"eye",
       [](C& c) -> std::optional<std::array<float, 3>>& { return c.raypipeView.camera.eye; }},
      {"u", [](C& c) -> std::optional<std::array<float, 3>>& { return c.raypipeView.camera.u; }},
      {"v", [](C& c) -> std::optional<std::array<float, 3>>& { return c.raypipeView.camera.v; }},
      {"w", [](C& c) -> std::optional<std::array<float, 3>>& { return c.raypipeView.camera.w; }},
  };
  for (const auto& [name, field] : registers)
    added.push_back(cameraRegister(std::string("raypipe.camera.") + name,
                                   std::string("ray pipe: camera register ") + name +
                                       " in hardware space (x and y swapped; empty: from camera.*)",
                                   field));
  added.push_back(integer("raypipe.level", "--level", "", -1, kPrgLevels - 1, camera,
                          "ray pipe: the seed's resolution level, 0 (20x15) to 5 (640x480); -1: "
                          "width x height",
                          [](C& c) -> int& { return c.raypipeView.level; }));
  for (Setting& setting : added) {
    setting.ignoredBecause = [](const RunConfig& c) {
      return c.architecture == Architecture::Raypipe ? std::string() : "architecture is rtu";
    };
    schema.push_back(std::move(setting));
  }
}

std::string ignoredAtRaypipeLevel(const RunConfig& c) {
  return c.architecture == Architecture::Raypipe && c.raypipeView.level >= 0
             ? "raypipe.level is " + std::to_string(c.raypipeView.level)
             : std::string();
}

// The RTU's own settings (its model's and its kinds' arithmetic) have no effect on the ray pipe.
void markRtuOnly(std::vector<Setting>& schema) {
  for (Setting& setting : schema) {
    if (!(setting.uses & (kUseModel | kUseArithmetic)) || setting.key == "architecture" ||
        setting.key.rfind("raypipe.", 0) == 0)
      continue;
    setting.ignoredBecause = [rtu = setting.ignoredBecause](const RunConfig& c) {
      if (c.architecture == Architecture::Raypipe) return std::string("architecture is raypipe");
      return rtu ? rtu(c) : std::string();
    };
  }
}

std::vector<Setting> makeSchema() {
  using C = RunConfig;
  constexpr unsigned model = kUseModel, arith = kUseArithmetic, scene = kUseScene,
                     camera = kUseCamera, buffers = kUseBuffers, sampling = kUseSampling;
  std::vector<Setting> s;
  s.push_back(choice(
      "model", "--model", {"golden", "lt", "ca"}, kUseModelChoice,
      "which model answers: ca (cycle-accurate SystemC, exact), lt (loosely-timed "
      "TLM-2.0, estimated cycles) or golden (untimed; cycles from golden costs)",
      [](C& c) -> ModelKind& { return c.model; }, modelKindName, parseModelKind));
  s.push_back(integer("lt.quantum", "--lt-quantum", "cycles", 1, 1e9, kUseModelChoice,
                      "loosely-timed model: global quantum of temporal decoupling",
                      [](C& c) -> uint64_t& { return c.rtu.ltQuantum; }));
  s.back().ignoredBecause = ignoredUnlessLooselyTimed;
  s.push_back(integer("cores", "--cores", "", 1, kMaxCores, model, "number of traversal cores",
                      [](C& c) -> int& { return c.rtu.cores; }));
  s.push_back(choice(
      "scheduler", "--scheduler", {"cfa", "rr", "fa"}, model,
      "cfa (cyclic first-available, the RTL), rr (round-robin) or fa (first-available)",
      [](C& c) -> SchedulerPolicy& { return c.rtu.scheduler; }, schedulerName,
      parseSchedulerPolicy));
  s.push_back(real("clock_mhz", "--clock-mhz", "MHz", kMinClockMhz, kMaxClockMhz, model,
                   "clock for rates and frame rates",
                   [](C& c) -> double& { return c.rtu.clockMhz; }));
  s.push_back(choice(
      "memory.kind", "--memory", {"ideal", "cached"}, model,
      "ideal (thesis ROM, every word at once) or cached (L1, L2, DRAM)",
      [](C& c) -> bool& { return c.rtu.memory.ideal; }, memoryKindName, parseMemoryKind));
  addCache(s, "l1", [](C& c) -> CacheConfig& { return c.rtu.memory.l1; });
  addCache(s, "l2", [](C& c) -> CacheConfig& { return c.rtu.memory.l2; });
  s.push_back(integer("memory.dram.latency", "--dram-latency", "cycles", 0, kMaxLatencyCycles,
                      model, "cycles from issuing a read to the start of its data",
                      [](C& c) -> uint32_t& { return c.rtu.memory.dram.latency; }));
  s.back().ignoredBecause = ignoredWithIdealMemory;
  s.push_back(real("memory.dram.bytes_per_cycle", "--dram-bytes-per-cycle", "bytes/cycle",
                   kMinBytesPerCycle, kMaxBytesPerCycle, model, "DRAM bus bandwidth",
                   [](C& c) -> double& { return c.rtu.memory.dram.bytesPerCycle; }));
  s.back().ignoredBecause = ignoredWithIdealMemory;
  s.push_back(realOrZero("host.in.bytes_per_cycle", "--host-in-bytes-per-cycle", "bytes/cycle",
                         kMinBytesPerCycle, kMaxBytesPerCycle, model,
                         "host input link rate, 32-byte records (0: one record a cycle)",
                         [](C& c) -> double& { return c.rtu.hostInput.bytesPerCycle; }));
  s.push_back(realOrZero("host.out.bytes_per_cycle", "--host-out-bytes-per-cycle", "bytes/cycle",
                         kMinBytesPerCycle, kMaxBytesPerCycle, model,
                         "host output link rate, 32-byte records (0: one record a cycle)",
                         [](C& c) -> double& { return c.rtu.hostOutput.bytesPerCycle; }));
  s.push_back(integer("warm_frames", "--warm-frames", "frames", 0, kMaxWarmFrames, model,
                      "frames of the same rays run through the caches before the measured one, "
                      "as a unit rendering frame after frame (0: cold caches)",
                      [](C& c) -> int& { return c.rtu.warmFrames; }));
  s.back().ignoredBecause = ignoredWithIdealMemory;
  s.push_back(integer("reorder", "--reorder", "results", 0, 1 << 24, model,
                      "reorder buffer capacity: results in submission order (0: none)",
                      [](C& c) -> int& { return c.rtu.reorderCapacity; }));
  s.push_back(integer("scene_manager.rays_in_flight", "--scene-rays-in-flight", "rays", 1, 1 << 16,
                      model, "rays the scene manager holds at once (animate --model ca)",
                      [](C& c) -> int& { return c.rtu.sceneManager.raysInFlight; }));
  s.push_back(integer("scene_manager.jobs_outstanding", "--scene-jobs-outstanding", "jobs", 1,
                      1 << 16, model, "jobs issued to the RTU and not yet returned, at most",
                      [](C& c) -> int& { return c.rtu.sceneManager.jobsOutstanding; }));
  s.push_back(integer("scene_manager.latency", "--scene-latency", "cycles", 0, kMaxLatencyCycles,
                      model, "cycles from taking a ray to its first job (sphere tests, sort)",
                      [](C& c) -> int& { return c.rtu.sceneManager.latency; }));
  s.push_back(integer("job_manager.stages", "--jm-stages", "cycles", 1, 64, model,
                      "job manager pipeline stages for t-value records (RTL: 6)",
                      [](C& c) -> int& { return c.rtu.jobManager.stages; }));
  s.push_back(integer("job_manager.ray_stages", "--jm-ray-stages", "cycles", 0, 64, model,
                      "extra stages for ray records: transform and t-parameters",
                      [](C& c) -> int& { return c.rtu.jobManager.rayStages; }));
  s.push_back(integer("job_manager.header_fetch", "--jm-header-fetch", "cycles", 0,
                      kMaxLatencyCycles, model, "cycles to fetch a model header, once per model",
                      [](C& c) -> int& { return c.rtu.jobManager.headerFetchCycles; }));
  // The SVO kind's set-up of ray records reads it; its key and place stay the job manager's.
  s.push_back(
      real("job_manager.epsilon", "--ray-epsilon", "", 0, 1, buffers,
           "ray records: direction components below epsilon times the largest count as zero",
           [](C& c) -> float& { return c.rtu.coreConfig<SvoKind>().epsilon; }));
  s.back().formerFlag = "--epsilon";
  s.back().ignoredBecause = [](const C& c) {
    return c.rays.empty() ? std::string("no ray records (rays) are given") : std::string();
  };
  // The architecture, the ray pipe's settings, then the RTU's kind of core and each kind's own.
  s.push_back(choice(
      "architecture", "--architecture", {"rtu", "raypipe"}, model | arith,
      "what is modelled: rtu (the thesis' RTU, cores of a kind) or raypipe (seed 001's ray pipe, "
      "the Tray Racer)",
      [](C& c) -> Architecture& { return c.architecture; }, architectureName, parseArchitecture));
  addRaypipeSettings(s);
  s.push_back(choice(
      "core", "--core", CoreKinds::names(), model | arith,
      "the kind of traversal core (" + CoreKinds::described() + ")",
      [](C& c) -> std::string& { return c.rtu.core; }, sameText, sameText));
  addSvoSettings(s);
  addBvhSettings(s);
  addBihSettings(s);
  addKdSettings(s);
  // The workload.
  s.push_back(choice(
      "scene", "--scene", proceduralSceneNames(), scene,
      "procedural scene, used when no scene file is given",
      [](C& c) -> std::string& { return c.scene.procedural; }, sameText, sameText));
  s.back().ignoredBecause = ignoredWithSceneFile;
  s.push_back(integer("scene.depth", "--depth", "levels", 1, 16, scene,
                      "octree depth of procedural scenes and meshes",
                      [](C& c) -> int& { return c.scene.depth; }));
  s.back().ignoredBecause = ignoredWithoutBuiltTree;
  s.push_back(integer("scene.seed", "--seed", "", 0, 9007199254740992.0, scene,
                      "seed of the random scenes (terrain, noise)",
                      [](C& c) -> uint64_t& { return c.scene.seed; }));
  s.back().ignoredBecause = ignoredWithSceneFile;
  s.push_back(integer("scene.root", "--root", "word", 0, 4294967295.0, scene,
                      "word address of the root descriptor",
                      [](C& c) -> uint32_t& { return c.scene.root; }));
  s.push_back(text(SettingKind::Path, "svo", "--svo", scene | buffers,
                   "SVO memory image (.svo, little-endian u32 words)",
                   [](C& c) -> std::string& { return c.scene.svoFile; }));
  s.push_back(
      text(SettingKind::Path, "mesh", "--mesh", scene,
           "triangle mesh to voxelize, or to build a triangle structure over (OBJ, PLY, OFF)",
           [](C& c) -> std::string& { return c.scene.meshFile; }));
  s.push_back(text(SettingKind::Path, "binvox", "--binvox", scene, "voxel file to import (.binvox)",
                   [](C& c) -> std::string& { return c.scene.binvoxFile; }));
  addAccelSettings(s);
  s.push_back(text(SettingKind::Path, "jobs", "--jobs", buffers,
                   "host input buffer (8 u32 per job record)",
                   [](C& c) -> std::string& { return c.jobs; }));
  s.push_back(text(SettingKind::Path, "rays", "--rays", buffers,
                   "ray buffer (8 u32 per world-space ray record)",
                   [](C& c) -> std::string& { return c.rays; }));
  addWorkloadSettings(s);
  s.push_back(integer("width", "--width", "pixels", 1, 1 << 14, camera, "image width",
                      [](C& c) -> int& { return c.camera.width; }));
  s.back().ignoredBecause = ignoredAtRaypipeLevel;
  s.push_back(integer("height", "--height", "pixels", 1, 1 << 14, camera, "image height",
                      [](C& c) -> int& { return c.camera.height; }));
  s.back().ignoredBecause = ignoredAtRaypipeLevel;
  s.push_back(vector("camera.position", "--camera", camera, "camera position x,y,z",
                     [](C& c) -> glm::dvec3& { return c.camera.position; }));
  s.push_back(vector("camera.look_at", "--look-at", camera, "point the camera looks at x,y,z",
                     [](C& c) -> glm::dvec3& { return c.camera.lookAt; }));
  s.push_back(vector("camera.up", "--up", camera, "camera up vector x,y,z",
                     [](C& c) -> glm::dvec3& { return c.camera.up; }));
  s.push_back(real("camera.fov", "--fov", "degrees", 1e-3, 179.999, camera,
                   "vertical field of view",
                   [](C& c) -> double& { return c.camera.verticalFovDegrees; }));
  s.push_back(real("camera.epsilon", "--camera-epsilon", "", 1e-30, 1, camera,
                   "camera rays: replaces exact zero direction components (thesis driver: 0.0001)",
                   [](C& c) -> double& { return c.epsilon; }));
  s.back().formerFlag = "--epsilon";
  // Sampled simulation (sampled_run.h).
  s.push_back(realOrZero("sample.fraction", "--sample", "", 1e-6, 1, sampling,
                         "simulate this fraction of the frame's rays as a stratified sample of "
                         "blocks and estimate the rest (0: every ray)",
                         [](C& c) -> double& { return c.sample.fraction; }));
  s.push_back(integer("sample.seed", "--sample-seed", "", 0, 9007199254740992.0, sampling,
                      "seed of the sampled blocks' places",
                      [](C& c) -> uint64_t& { return c.sample.seed; }));
  s.back().ignoredBecause = ignoredWithoutSampling;
  s.push_back(integer("sample.block", "--sample-block", "rays", 0, 1 << 24, sampling,
                      "rays counted per sampled block (0: chosen from the fraction)",
                      [](C& c) -> uint64_t& { return c.sample.blockRays; }));
  s.back().ignoredBecause = ignoredWithoutSampling;
  s.push_back(integer("sample.warmup", "--sample-warmup", "rays", 0, 1 << 24, sampling,
                      "rays simulated before each block and not counted (0: 512, or 32 a core)",
                      [](C& c) -> uint64_t& { return c.sample.warmupRays; }));
  s.back().ignoredBecause = ignoredWithoutSampling;
  markRtuOnly(s);
  return s;
}

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string Setting::range() const {
  switch (kind) {
    case SettingKind::Choice: {
      std::string all;
      for (const std::string& c : choices) all += (all.empty() ? "" : "|") + c;
      return all;
    }
    case SettingKind::Bytes:
      return formatBytes(static_cast<uint64_t>(min)) + " .. " +
             formatBytes(static_cast<uint64_t>(max));
    case SettingKind::Integer:
    case SettingKind::Real:
      return (zeroAllowed ? "0 or " : "") + formatReal(min) + " .. " + formatReal(max);
    case SettingKind::Flag: return "true|false";
    case SettingKind::Vector: return "x,y,z";
    case SettingKind::Text: return "text";
    default: return "file";
  }
}

bool Setting::quotedInFiles() const {
  return kind != SettingKind::Integer && kind != SettingKind::Real && kind != SettingKind::Flag;
}

const std::vector<Setting>& configSchema() {
  static const std::vector<Setting> schema = makeSchema();
  return schema;
}

const Setting& findSetting(const std::string& key) {
  const std::vector<Setting>& schema = configSchema();
  for (const Setting& s : schema)
    if (s.key == key) return s;
  const Setting* nearest = &schema.front();
  for (const Setting& s : schema)
    if (editDistance(key, s.key) < editDistance(key, nearest->key)) nearest = &s;
  throw std::invalid_argument("unknown setting '" + key + "'; did you mean '" + nearest->key +
                              "'? (rtusim config --list shows every key)");
}

uint64_t parseBytes(const std::string& text, const std::string& key) {
  const std::string value = trim(text);
  const size_t unitStart = value.find_first_not_of("0123456789.");
  const std::string digits = trim(value.substr(0, unitStart));
  const std::string unit = unitStart == std::string::npos ? "" : trim(value.substr(unitStart));
  static const std::vector<std::pair<std::string, double>> units = {
      {"", 1},     {"B", 1},    {"KiB", 1024.0}, {"MiB", 1048576.0}, {"GiB", 1073741824.0},
      {"kB", 1e3}, {"KB", 1e3}, {"MB", 1e6},     {"GB", 1e9}};
  const auto found =
      std::find_if(units.begin(), units.end(), [&](const auto& u) { return u.first == unit; });
  if (digits.empty() || found == units.end())
    fail(key, "'" + text + "' is not a size (e.g. 4096, 4KiB, 1MiB)");
  const double bytes = parseNumber(digits, key, false) * found->second;
  if (bytes != std::floor(bytes) || bytes > 9e15)
    fail(key, "'" + text + "' is not a whole number of bytes");
  return static_cast<uint64_t>(bytes);
}

std::string formatBytes(uint64_t bytes) {
  static const char* const units[] = {"GiB", "MiB", "KiB"};
  for (int i = 0; i < 3; ++i) {
    const uint64_t scale = uint64_t{1} << (10 * (3 - i));
    if (bytes >= scale && bytes % scale == 0) return std::to_string(bytes / scale) + units[i];
  }
  return std::to_string(bytes);
}

}  // namespace rtu
