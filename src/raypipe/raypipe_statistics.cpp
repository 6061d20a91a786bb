#include "raypipe/raypipe_statistics.h"

#include <algorithm>

namespace rtu {
namespace {

double ratio(uint64_t part, uint64_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

uint64_t counted(int64_t value) { return value < 0 ? 0 : static_cast<uint64_t>(value); }

// The cycles between two items at a unit's full rate: the PRG takes a pixel on v0 and SINT a ray
// on v2 of the shared phase; every other unit can take one a cycle.
uint64_t fullRateInterval(const std::string& unit, const RaypipeConfig& config) {
  if (unit == raypipeUnitName(RaypipeUnit::Prg)) return counted(config.latency.prgInterval);
  if (unit == raypipeUnitName(RaypipeUnit::Sint)) return counted(config.latency.sintInterval);
  return 1;
}

// How many of a unit the pipe has: one tarb output, tcache and TRAV per traversal unit.
uint64_t unitCopies(const std::string& unit, const RaypipeConfig& config) {
  for (RaypipeUnit u : {RaypipeUnit::Tarb, RaypipeUnit::Tcache, RaypipeUnit::Trav,
                        RaypipeUnit::TravMath, RaypipeUnit::TravDecide})
    if (unit == raypipeUnitName(u)) return counted(config.traversalUnits);
  return 1;
}

// The first unit of the highest utilisation, in the pipe's order.
const RaypipeUnitStatistics* busiest(const RaypipeStatistics& s) {
  const RaypipeUnitStatistics* best = nullptr;
  for (const RaypipeUnitStatistics& unit : s.units)
    if (!best || s.utilisation(unit) > s.utilisation(*best)) best = &unit;
  return best;
}

}  // namespace

RaypipeStatistics RaypipeStatistics::of(const RaypipeCycleRun& run, const RaypipeConfig& config) {
  RaypipeStatistics s;
  s.rays = run.results.size();
  s.totalCycles = counted(run.frameCycles);
  s.clockMhz = config.clockMHz;
  for (const RaypipeCycleResult& r : run.results) {
    s.hits += r.hit;
    s.boxMisses += r.boxMiss;
    s.nodes += r.counts.nodes;
    s.leaves += r.counts.leaves;
    s.triangleTests += r.counts.triangleTests;
    s.pushes += r.counts.pushes;
    s.dropped += r.counts.dropped;
    s.restarts += r.counts.restarts;
  }
  s.rayIds = counted(config.raysInFlight);
  s.mostRayIdsHeld = counted(run.maxRaysInFlight);
  s.lastWriteCycle = counted(run.lastWriteCycle);
  s.writerWaits = counted(run.writerWaits);
  s.staleListHits = counted(run.staleListHits);
  for (const RaypipeUnitActivity& unit : run.units)
    s.units.push_back({unit.unit, counted(unit.busy), counted(unit.stall),
                       fullRateInterval(unit.unit, config), unitCopies(unit.unit, config)});
  for (const RaypipeFifoPeak& fifo : run.fifos)
    s.fifos.push_back({fifo.fifo, counted(fifo.depth), counted(fifo.peak)});
  for (const RaypipeCacheCounts& c : run.caches)
    s.caches.push_back({c.cache, counted(c.hits), counted(c.misses), counted(c.fills),
                        counted(c.reissues), counted(c.stalls)});
  s.dramReads = counted(run.dram.reads);
  s.dramBytes = counted(run.dram.bytes);
  s.dramBusyCycles = counted(run.dram.busyCycles);
  s.hostSeconds = run.hostSeconds;
  return s;
}

double RaypipeStatistics::cyclesPerRay() const { return ratio(totalCycles, rays); }
double RaypipeStatistics::frameMilliseconds() const {
  return static_cast<double>(totalCycles) / (clockMhz * 1e3);
}
double RaypipeStatistics::framesPerSecond() const {
  return totalCycles == 0 ? 0.0 : clockMhz * 1e6 / static_cast<double>(totalCycles);
}
double RaypipeStatistics::raysPerSecond() const {
  return static_cast<double>(rays) * framesPerSecond();
}

double RaypipeStatistics::utilisation(const RaypipeUnitStatistics& unit) const {
  return ratio(unit.busy * unit.interval, unit.copies * totalCycles);
}

double RaypipeStatistics::heldUtilisation(const RaypipeUnitStatistics& unit) const {
  return ratio((unit.busy + unit.stall) * unit.interval, unit.copies * totalCycles);
}

// The SRAM writer held a pixel (took it, or waited for the VGA reader) in most cycles of the frame
// while taking one in fewer: the pixels left the pipe at the rate the reader's window let them,
// and no unit was saturated by its own work.
bool RaypipeStatistics::vgaWindowBounds() const {
  const RaypipeUnitStatistics* unit = busiest(*this);
  if (writerWaits == 0 || (unit && utilisation(*unit) >= kSaturated)) return false;
  const RaypipeUnitStatistics* writer = pixelWriter();
  return writer && heldUtilisation(*writer) >= kSaturated;
}

const RaypipeUnitStatistics* RaypipeStatistics::pixelWriter() const {
  for (const RaypipeUnitStatistics& unit : units)
    if (unit.unit == raypipeUnitName(RaypipeUnit::PixelWriter)) return &unit;
  return nullptr;
}

std::string RaypipeStatistics::limit() const {
  if (vgaWindowBounds()) return kVgaWindow;
  const RaypipeUnitStatistics* unit = busiest(*this);
  return unit && utilisation(*unit) >= kSaturated ? unit->unit : "none";
}

double RaypipeStatistics::limitUtilisation() const {
  if (vgaWindowBounds()) return heldUtilisation(*pixelWriter());
  const RaypipeUnitStatistics* unit = busiest(*this);
  return unit ? utilisation(*unit) : 0.0;
}

const StatisticGroup<RaypipeUnitStatistics>& RaypipeUnitStatistics::declaration() {
  using U = RaypipeUnitStatistics;
  static const StatisticGroup<U> group =
      StatisticGroup<U>("a unit of the ray pipe")
          .setting(Statistic("unit", "", "its name (docs/raypipe.md, the units' table)"), &U::unit)
          .count(Statistic("busy", "cycles", "cycles the unit took an item"), &U::busy)
          .count(Statistic("stall", "cycles",
                           "cycles an item was offered to it and not taken (SINT's include the "
                           "wait for its phase and for a ray id)"),
                 &U::stall)
          .setting(Statistic("interval", "cycles",
                             "cycles between two items at its full rate: latency.prg_interval, "
                             "latency.sint_interval, 1 for the others"),
                   &U::interval)
          .setting(Statistic("copies", "units",
                             "how many of it the pipe has (busy and stall are their sum): "
                             "raypipe.traversal_units for tarb, tcache, trav, trav_math and "
                             "trav_decide, 1 for the others"),
                   &U::copies);
  return group;
}

const StatisticGroup<RaypipeFifoStatistics>& RaypipeFifoStatistics::declaration() {
  using F = RaypipeFifoStatistics;
  static const StatisticGroup<F> group =
      StatisticGroup<F>("a FIFO of the ray pipe")
          .setting(Statistic("fifo", "", "its name"), &F::fifo)
          .setting(Statistic("depth", "entries", "its depth (raypipe.fifo.*)"), &F::depth)
          .maximum(Statistic("peak", "entries", "the most entries it held"), &F::peak);
  return group;
}

const StatisticGroup<RaypipeCacheStatistics>& RaypipeCacheStatistics::declaration() {
  using C = RaypipeCacheStatistics;
  static const StatisticGroup<C> group =
      StatisticGroup<C>("a set-associative cache of the ray pipe")
          .setting(Statistic("cache", "", "its name (tcache, tcache_1, lcache, icache)"), &C::cache)
          .count(Statistic("hits", "lookups",
                           "items that found their line (a filled line's own item among them)"),
                 &C::hits)
          .count(Statistic("misses", "lookups",
                           "items that did not (an item missing again counts again)"),
                 &C::misses)
          .count(Statistic("fills", "lines", "lines read from DRAM"), &C::fills)
          .count(Statistic("reissues", "items", "missed items sent through the cache again"),
                 &C::reissues)
          .count(Statistic("stalls", "cycles",
                           "cycles an item was offered to the cache and refused (a reissue "
                           "going first, the reissue FIFO full, the hit FIFO's credit)"),
                 &C::stalls)
          .derived(Statistic("hit_rate", "", "hits / (hits + misses)"), [](const C& c) {
            return c.hits + c.misses == 0
                       ? 0.0
                       : static_cast<double>(c.hits) / static_cast<double>(c.hits + c.misses);
          });
  return group;
}

const StatisticGroup<RaypipeStatistics>& RaypipeStatistics::declaration() {
  using S = RaypipeStatistics;
  using Unit = PartOf<S, RaypipeUnitStatistics>;
  static const StatisticGroup<Unit> unitLayout =
      StatisticGroup<Unit>("a unit of the ray pipe")
          .own<S, RaypipeUnitStatistics>()
          .derived(Statistic("utilisation", "", "busy · interval / (copies · total_cycles)"),
                   [](const Unit& u) { return u.whole.utilisation(u.values); });
  static const StatisticGroup<S> group =
      StatisticGroup<S>(
          "a frame of the ray pipe (architecture = raypipe): --stats files, \"statistics\" of "
          "its fps and sweep rows")
          .count(Statistic("rays", "rays", "the primary ray generator's rays (pixels)"), &S::rays)
          .count(Statistic("total_cycles", "cycles",
                           "the frame's cycles: from the PRG's first to the last pixel leaving "
                           "the shader"),
                 &S::totalCycles)
          .derived(Statistic("cycles_per_ray", "cycles", "total_cycles / rays"), &S::cyclesPerRay)
          .setting(Statistic("clock_mhz", "MHz", "raypipe.clock_mhz"), &S::clockMhz)
          .derived(Statistic("frame_ms", "ms", "total_cycles at the clock"), &S::frameMilliseconds)
          .derived(Statistic("fps", "frames/s", "frames per second at the clock"),
                   &S::framesPerSecond)
          .derived(Statistic("rays_per_second", "rays/s", "rays per second at the clock"),
                   &S::raysPerSecond)
          .derived(Statistic("limit", "",
                             "the unit of the highest utilisation, when it reaches 0.8; "
                             "vga_window when the SRAM writer took or waited for the VGA reader "
                             "with a pixel in 0.8 of the cycles instead (docs/raypipe.md); none "
                             "below"),
                   &S::limit)
          .derived(Statistic("limit_utilisation", "",
                             "the highest utilisation, saturated or not; with vga_window the "
                             "writer's share of the cycles taking or waiting"),
                   &S::limitUtilisation)
          .count(Statistic("hits", "rays", "rays that hit a triangle"), &S::hits)
          .derived(Statistic("misses", "rays", "rays that entered the scene box and hit nothing"),
                   [](const S& s) { return s.rays - s.hits - s.boxMisses; })
          .count(Statistic("box_misses", "rays", "rays that missed the scene box (SINT)"),
                 &S::boxMisses)
          .count(Statistic("traversal/nodes", "nodes", "node records read, interior and leaf"),
                 &S::nodes)
          .count(Statistic("traversal/leaves", "nodes", "of which leaves"), &S::leaves)
          .count(Statistic("traversal/triangle_tests", "tests", "triangles through INT"),
                 &S::triangleTests)
          .count(Statistic("traversal/pushes", "entries", "short-stack pushes"), &S::pushes)
          .count(Statistic("traversal/dropped", "entries",
                           "stack entries overwritten by a push onto a full short stack"),
                 &S::dropped)
          .count(Statistic("traversal/restarts", "restarts", "restarts from the restart node"),
                 &S::restarts)
          .setting(Statistic("ray_ids/available", "ids", "raypipe.rays_in_flight"), &S::rayIds)
          .maximum(Statistic("ray_ids/most_held", "ids", "the most ray ids held at once"),
                   &S::mostRayIdsHeld)
          .count(Statistic("writer/waits", "cycles",
                           "cycles a pixel waited for the VGA reader (raypipe.vga_window)"),
                 &S::writerWaits)
          .maximum(Statistic("writer/last_write_cycle", "cycle",
                             "the cycle the SRAM writer took the last pixel"),
                   &S::lastWriteCycle)
          .count(Statistic("stale_list_hits", "rays",
                           "rays that ended as a miss with a hit kept in the list record (the "
                           "RTL would leave it to the id's next ray)"),
                 &S::staleListHits)
          .list(Statistic("units", "", "per unit, in the pipe's order"), &S::units, &unitLayout)
          .list(Statistic("fifos", "", "per FIFO"), &S::fifos)
          .list(Statistic("caches", "",
                          "per cache with raypipe.cache = set_associative (none with block_ram)"),
                &S::caches)
          .count(Statistic("dram/reads", "lines",
                           "lines read from DRAM through the memory request arbiter"),
                 &S::dramReads)
          .count(Statistic("dram/bytes", "bytes", "bytes read from DRAM"), &S::dramBytes)
          .count(Statistic("dram/busy_cycles", "cycles", "cycles the DRAM's data bus transferred"),
                 &S::dramBusyCycles)
          .setting(Statistic("simulation/model", "",
                             "what answered: raypipe, the pipe's timed model"),
                   &S::model)
          .real(Statistic("simulation/host_seconds", "s",
                          "host time of the run (differs run to run)"),
                &S::hostSeconds)
          .derived(Statistic("simulation/rays_per_host_second", "rays/s", "rays per host second"),
                   [](const S& s) { return s.hostSeconds > 0 ? s.rays / s.hostSeconds : 0.0; });
  return group;
}

}  // namespace rtu
