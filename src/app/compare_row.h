#pragma once
// One architecture's row of `rtusim compare` (issue 30): the scene built for it, the frame's run
// as a row of fps and sweep runs it (explore/exploration_run.h: runFrameRow, so the row's
// statistics are those of `rtusim fps` with the same settings), the figures the comparison shows,
// taken from that row's statistics, and its image against the float64 reference
// (explore/frame_agreement.h), with the difference image.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/configuration.h"
#include "explore/reference_frame.h"
#include "geometry/triangle_oracle.h"

namespace rtu {

// What an architecture is run with besides its configuration.
struct CompareTarget {
  std::string name;    // svo, bvh, bih, kd, raypipe
  std::string preset;  // the preset its configuration started from ("" for none)
  Configuration configuration;
  // The ray pipe traces the scene's triangles where the model sits (a mesh in its own space, which
  // this places in the world), so its camera is the frame's moved there.
  ModelPlacement raypipePlacement;
  std::string differenceImage;  // where its difference image goes, or ""
};

// The float64 reference: the scene's triangles in the world and the frame's nearest hits, one per
// pixel of the frame's camera.
struct CompareReference {
  const ReferenceTracer& tracer;
  std::vector<std::optional<OracleHit>> frame;
};

// The row: "architecture", "preset", "status", "error", "scene", "structure", "image_bytes",
// "build_seconds", "figures" (compareFigures), "agreement" and "row" (the fps row in full).
// Failures are rows with "status": "failed" and the error.
// The SVO and triangle kinds are measured against `reference.frame`; the ray pipe against its own
// rays (its PRG's, through a corner of each pixel) traced by `reference.tracer`.
nlohmann::ordered_json compareRow(const CompareTarget& target, const CompareReference& reference);

// The figures of a row's statistics (an RTU kind's or the ray pipe's): frame cycles and rate,
// cycles per ray, bytes per ray from the core (its fetches), the L2 (L1 refills) and DRAM, L1 and
// L2 hit rates, nodes and triangle tests per ray, the cores' (or the pipe's busiest unit's)
// utilisation and the limit, the resource estimate's memory bits, 18 Kbit block RAMs, DSP48E
// slices and multipliers with the frame rate per block RAM and per DSP48E (the row's
// "resources", explore/architecture_resources.h); null where the architecture has no such figure.
nlohmann::ordered_json compareFigures(const nlohmann::ordered_json& row);

// The CSV's columns and a row's fields.
const std::vector<std::string>& compareColumns();
std::vector<std::string> compareFields(const nlohmann::ordered_json& row);

}  // namespace rtu
