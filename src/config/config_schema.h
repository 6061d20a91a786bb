#pragma once
// The configuration schema: every setting of a run declared once, with its hierarchical key,
// its command-line spelling, type, unit, default, range or choices and one line of
// documentation. Command-line options, configuration files, presets, `--set`, validation,
// `config --dump` and `config --list` are all derived from these declarations.

#include <functional>
#include <string>
#include <vector>

#include "config/run_config.h"

namespace rtu {

enum class SettingKind { Integer, Real, Bytes, Choice, Text, Path, Flag, Vector };

// Which part of a run a setting configures; each command names the parts it uses.
enum SettingUse : unsigned {
  kUseModel = 1u << 0,        // the timed RTU model: cores, memory, links, job manager
  kUseArithmetic = 1u << 1,   // number format and stack, golden model too
  kUseScene = 1u << 2,        // procedural scene or scene file
  kUseCamera = 1u << 3,       // camera and frame size
  kUseBuffers = 1u << 4,      // job or ray buffers and the .svo they run on
  kUseSampling = 1u << 5,     // sampled simulation of fps and sweep rows
  kUseModelChoice = 1u << 6,  // which model answers: golden, lt or ca
  kUseAccel = 1u << 7,        // the acceleration structure `build` makes and its builder
  kUseWorkload = 1u << 8,     // a frame's passes beyond its primary rays (render, fps, sweep,
                              // compare) and how their rays are spawned
};

struct Setting {
  std::string key;   // "memory.l1.size"
  std::string flag;  // its short command-line spelling, "--l1-size"; may be empty
  // An older spelling still accepted: an alias where the command has no other setting of that
  // spelling, else deprecated, with the first such setting's meaning (schema_flags.cpp).
  std::string formerFlag;
  SettingKind kind = SettingKind::Integer;
  std::string unit;  // "bytes", "cycles", "MHz", ...
  std::string doc;
  std::vector<std::string> choices;  // Choice
  double min = 0, max = 0;           // Integer, Real, Bytes (inclusive)
  bool zeroAllowed = false;          // Real: 0 (unlimited) is accepted besides min .. max
  unsigned uses = 0;                 // SettingUse bits

  // The value as text that `assign` reads back (sizes in bytes, vectors as "x,y,z").
  std::function<std::string(const RunConfig&)> get;
  // Parses and stores; throws std::invalid_argument with a message naming the key.
  std::function<void(RunConfig&, const std::string&)> assign;
  // Why the setting has no effect in this configuration, or empty when it has one.
  std::function<std::string(const RunConfig&)> ignoredBecause;

  std::string range() const;   // "1 .. 1024", "cfa|rr|fa", ...
  bool quotedInFiles() const;  // written as a TOML string
};

// Every setting, in the order `config --list` and `--dump` show them.
const std::vector<Setting>& configSchema();
// Throws std::invalid_argument for an unknown key, naming the nearest known one.
const Setting& findSetting(const std::string& key);

// "4KiB", "1MiB", "64", "2 GiB", "1kB" -> bytes; throws std::invalid_argument naming `key`.
uint64_t parseBytes(const std::string& text, const std::string& key);
// 4096 -> "4KiB", 1000 -> "1000".
std::string formatBytes(uint64_t bytes);

}  // namespace rtu
