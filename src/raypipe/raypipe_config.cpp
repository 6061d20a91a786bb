#include "raypipe/raypipe_config.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace rtu {
namespace {

void atLeast(const char* key, int value, int least) {
  if (value < least)
    throw std::invalid_argument(std::string(key) + " = " + std::to_string(value) +
                                ": must be at least " + std::to_string(least));
}

void atMost(const char* key, int value, int most, const char* why) {
  if (value > most)
    throw std::invalid_argument(std::string(key) + " = " + std::to_string(value) + ": at most " +
                                std::to_string(most) + " (" + why + ")");
}

}  // namespace

void RaypipeConfig::validate() const {
  atLeast("raypipe.traversal_units", traversalUnits, 1);
  atMost("raypipe.traversal_units", traversalUnits, 2,
         "the RTL's designs: t5.sv has 1, raypipe_2trav.sv 2; the shortstack has ports for 2");
  atLeast("raypipe.short_stack_depth", shortStackDepth, 1);
  atMost("raypipe.short_stack_depth", shortStackDepth, 7, "the ray's 3-bit ss_num");
  atLeast("raypipe.rays_in_flight", raysInFlight, 1);
  atMost("raypipe.rays_in_flight", raysInFlight, 512, "the 9-bit rayID");
  const std::pair<const char*, int> positive[] = {
      {"raypipe.latency.prg", latency.prg},
      {"raypipe.latency.prg_interval", latency.prgInterval},
      {"raypipe.latency.sint", latency.sint},
      {"raypipe.latency.sint_interval", latency.sintInterval},
      {"raypipe.latency.trav_math", latency.travMath},
      {"raypipe.latency.intersection", latency.intersection},
      {"raypipe.latency.memory_read", latency.memoryRead},
      {"raypipe.fifo.prg", fifo.prg},
      {"raypipe.fifo.sint", fifo.sint},
      {"raypipe.fifo.tarb", fifo.tarb},
      {"raypipe.fifo.larb", fifo.larb},
      {"raypipe.fifo.trav_leaf", fifo.travLeaf},
      {"raypipe.fifo.trav_math", fifo.travMath},
      {"raypipe.fifo.int_list", fifo.intList},
      {"raypipe.fifo.int_larb", fifo.intLarb},
      {"raypipe.fifo.int_shader", fifo.intShader},
      {"raypipe.fifo.memory_out", fifo.memoryOut},
      {"raypipe.fifo.pixel_buffer", fifo.pixelBuffer},
  };
  for (const auto& [key, value] : positive) atLeast(key, value, 1);
  const std::pair<const char*, int> lines[] = {
      {"raypipe.cache_lines.tcache", caches.tcacheLines},
      {"raypipe.cache_lines.lcache", caches.lcacheLines},
      {"raypipe.cache_lines.icache", caches.icacheLines},
  };
  for (const auto& [key, value] : lines) {
    atLeast(key, value, 1);
    if ((value & (value - 1)) != 0)
      throw std::invalid_argument(std::string(key) + " = " + std::to_string(value) +
                                  ": must be a power of two (the RTL's index bits)");
  }
  atLeast("raypipe.dram.latency", caches.dramLatency, 1);
  if (!(caches.dramBytesPerCycle > 0))
    throw std::invalid_argument("raypipe.dram.bytes_per_cycle: must be positive");
  if (vgaPhase < 0)
    throw std::invalid_argument("raypipe.vga_phase: must not be negative (cycles from reset)");
  if (!(clockMHz > 0))
    throw std::invalid_argument("raypipe.clock_mhz: must be a positive frequency");
}

}  // namespace rtu
