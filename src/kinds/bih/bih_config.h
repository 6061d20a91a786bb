#pragma once
// The BIH core's own settings (RtuConfig::coreConfig<BihKind<>>(); the schema's keys in
// src/config/config_schema.cpp, "addBihSettings"): the early-out option, the triangle unit's
// cycles (bih_timing.h) and the number formats a BIH is built with (accel.bih_format).

#include <cstdint>
#include <string>

#include "kinds/bih/bih_timing.h"
#include "kinds/bih/fixed_format.h"

namespace rtu {

constexpr uint32_t kMaxBihUnitCycles = 1024;

struct BihConfig {
  bool earlyOut = false;  // S4 §3.4 L577: not implemented in the seed; an option here
  BihCycles cycles;
  // The formats `build` and `render` quantise a scene with (accel.bih_format). A core reads its
  // image's own formats from the image's header: the records were rounded in them.
  FixedTriangleFormat format = kC99Format;

  // Throws std::invalid_argument naming the setting (bih.triangle.latency,
  // bih.triangle.interval) for units of other than 1 to kMaxBihUnitCycles cycles or an interval
  // longer than the latency, and naming accel.bih_format for a format
  // validateFixedTriangleFormat refuses.
  void validate() const;
};

// The setting's names: "c99" (kC99Format), "vhdl" (kVhdlFormat); the parser throws
// std::invalid_argument for another name, and the printer names any other format by its fields.
std::string bihFormatName(const FixedTriangleFormat& format);
FixedTriangleFormat parseBihFormat(const std::string& name);

}  // namespace rtu
