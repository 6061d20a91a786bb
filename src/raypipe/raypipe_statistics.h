#pragma once
// The statistics of a timed frame of seed 001's ray pipe (issue 29): `render --architecture raypipe
// --stats`, and the "statistics" of its fps and sweep rows. Taken from a run of the timed model or
// the per-cycle reference (RaypipeCycleRun, raypipe_run.h) and the settings; declared once
// (base/statistics.h), so the JSON, `rtusim stats --list` and the keys test
// (tests/data/raypipe_statistics_keys.txt) follow from the declaration. The keys an RTU run also
// has (rays, total_cycles, cycles_per_ray, clock_mhz, frame_ms, fps, rays_per_second, limit,
// limit_utilisation, simulation/*) mean the same, so the fps and sweep CSV columns of those keys
// are filled for the pipe's rows too; docs/raypipe.md, "Exploring the pipe", lists every key.

#include <cstdint>
#include <string>
#include <vector>

#include "base/statistics.h"
#include "raypipe/raypipe_config.h"
#include "raypipe/raypipe_run.h"

namespace rtu {

// One unit's activity (RaypipeUnitActivity) with the cycles between two items at its full rate:
// the PRG's and SINT's issue intervals, 1 for every other unit; and how many of it the pipe has
// (its busy and stall cycles are their sum): raypipe.traversal_units for tarb's outputs, tcache,
// trav, trav_math and trav_decide, 1 for every other unit.
struct RaypipeUnitStatistics {
  std::string unit;
  uint64_t busy = 0, stall = 0;
  uint64_t interval = 1;
  uint64_t copies = 1;

  static const StatisticGroup<RaypipeUnitStatistics>& declaration();
};

struct RaypipeFifoStatistics {
  std::string fifo;
  uint64_t depth = 0, peak = 0;

  static const StatisticGroup<RaypipeFifoStatistics>& declaration();
};

// One cache's counts with raypipe.cache = set_associative (RaypipeCacheCounts, raypipe_cache.h).
struct RaypipeCacheStatistics {
  std::string cache;
  uint64_t hits = 0, misses = 0, fills = 0, reissues = 0, stalls = 0;

  static const StatisticGroup<RaypipeCacheStatistics>& declaration();
};

struct RaypipeStatistics {
  uint64_t rays = 0;
  uint64_t totalCycles = 0;  // the frame's cycles: cycle 0 (the PRG's first) to the last exit
  double clockMhz = 50;
  uint64_t hits = 0, boxMisses = 0;
  // The golden traversal's counts summed over the rays (KdRayCounts).
  uint64_t nodes = 0, leaves = 0, triangleTests = 0, pushes = 0, dropped = 0, restarts = 0;
  uint64_t rayIds = 0, mostRayIdsHeld = 0;
  uint64_t lastWriteCycle = 0, writerWaits = 0;
  uint64_t staleListHits = 0;
  std::vector<RaypipeUnitStatistics> units;
  std::vector<RaypipeFifoStatistics> fifos;
  std::vector<RaypipeCacheStatistics> caches;  // set_associative only
  uint64_t dramReads = 0, dramBytes = 0, dramBusyCycles = 0;
  std::string model = "raypipe";  // what answered: the pipe's timed model (or its reference)
  double hostSeconds = 0;

  static RaypipeStatistics of(const RaypipeCycleRun& run, const RaypipeConfig& config);

  double cyclesPerRay() const;
  double frameMilliseconds() const;
  double framesPerSecond() const;
  double raysPerSecond() const;
  // A unit's share of its full rate over the frame: busy · interval / (copies · total cycles).
  double utilisation(const RaypipeUnitStatistics& unit) const;
  // A unit's share of its full rate over the frame busy or offered an item it could not take
  // (held back by what follows it): (busy + stall) · interval / (copies · total cycles).
  double heldUtilisation(const RaypipeUnitStatistics& unit) const;
  // The VGA reader's window bounds the frame: no unit reaches kSaturated by its own work, and the
  // SRAM writer took a pixel or waited for the reader with one in kSaturated of the cycles (its
  // waits are its stall), so the pixels left at the rate the window let them (docs/raypipe.md,
  // "Exploring the pipe").
  bool vgaWindowBounds() const;
  const RaypipeUnitStatistics* pixelWriter() const;  // null when the run has none
  // The unit of the highest utilisation when it reaches kSaturated (the RTU's rule,
  // docs/exploration.md §2); else kVgaWindow when vgaWindowBounds(), with the writer's held
  // utilisation; else "none"; the highest utilisation, saturated or not.
  std::string limit() const;
  double limitUtilisation() const;
  static constexpr double kSaturated = 0.8;
  static constexpr const char* kVgaWindow = "vga_window";

  static const StatisticGroup<RaypipeStatistics>& declaration();
};

}  // namespace rtu
