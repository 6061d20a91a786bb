#include "raypipe/raypipe_resources.h"

namespace rtu {
namespace {

constexpr auto kFloat = NumberKind::Float;

// As built, full-capacity block RAMs; set-associative (cache.sv), two ways of the configured lines
// and a tag store of a byte a way.
void addCaches(const RaypipeConfig& config, ResourceEstimate& estimate) {
  if (config.cache != RaypipeCacheKind::SetAssociative) {
    estimate.memories.insert(estimate.memories.end(),
                             {{"tcache", 512, 384}, {"lcache", 1024, 256}, {"icache", 1024, 288}});
    return;
  }
  const RaypipeCacheSettings& s = config.caches;
  estimate.memories.insert(estimate.memories.end(), {{"tcache", s.tcacheLines, 384, 2},
                                                     {"tcache tags", s.tcacheLines, 16},
                                                     {"lcache", s.lcacheLines, 256, 2},
                                                     {"lcache tags", s.lcacheLines, 16},
                                                     {"icache", s.icacheLines, 288, 2},
                                                     {"icache tags", s.icacheLines, 16}});
}

void addFifos(const RaypipeConfig& config, ResourceEstimate& estimate) {
  const RaypipeFifoDepths& fifo = config.fifo;
  const int trav = config.traversalUnits;
  estimate.memories.insert(estimate.memories.end(), {{"prg fifo", fifo.prg, 211},
                                                     {"sint to tarb fifo", fifo.sint, 96},
                                                     {"sint to shortstack fifo", fifo.sint, 48},
                                                     {"sint to shader fifo", fifo.sint, 28},
                                                     {"tarb fifo", fifo.tarb, 96},
                                                     {"larb fifo", fifo.larb, 37},
                                                     {"trav leaf fifo", fifo.travLeaf, 41, trav},
                                                     {"trav math fifo", fifo.travMath, 144, trav},
                                                     {"int to list fifo", fifo.intList, 129},
                                                     {"int to larb fifo", fifo.intLarb, 36},
                                                     {"int to shader fifo", fifo.intShader, 9},
                                                     {"pixel buffer", fifo.pixelBuffer, 35}});
}

void addRayArrays(const RaypipeConfig& config, ResourceEstimate& estimate) {
  const int rays = config.raysInFlight;
  estimate.memories.insert(estimate.memories.end(),
                           {{"ray stores", rays, 192, config.traversalUnits + 2},
                            {"short stack", rays, 48, config.shortStackDepth},
                            {"restart nodes", rays, 48},
                            {"shader ray ids", rays, 9},
                            {"shader pixel ids", rays, 19}});
}

}  // namespace

ResourceEstimate raypipeResources(const RaypipeConfig& config) {
  ResourceEstimate estimate;
  addCaches(config, estimate);
  addFifos(config, estimate);
  addRayArrays(config, estimate);
  const int trav = config.traversalUnits;
  estimate.units = {{"prg", ArithmeticKind::Multiplier, kFloat, 32, 11},
                    {"prg", ArithmeticKind::Adder, kFloat, 32, 8},
                    {"sint", ArithmeticKind::Adder, kFloat, 32, 2},
                    {"sint", ArithmeticKind::Divider, kFloat, 32, 2},
                    {"sint", ArithmeticKind::Comparator, kFloat, 32, 5},
                    {"trav", ArithmeticKind::Adder, kFloat, 32, trav},
                    {"trav", ArithmeticKind::Divider, kFloat, 32, trav},
                    {"trav", ArithmeticKind::Comparator, kFloat, 32, 3 * trav},
                    {"int", ArithmeticKind::Multiplier, kFloat, 32, 20},
                    {"int", ArithmeticKind::Adder, kFloat, 32, 18},
                    {"int", ArithmeticKind::Divider, kFloat, 32, 1},
                    {"int", ArithmeticKind::Comparator, kFloat, 32, 3},
                    {"shortstack", ArithmeticKind::Comparator, kFloat, 32, 1},
                    {"list", ArithmeticKind::Comparator, kFloat, 32, 1}};
  return estimate;
}

}  // namespace rtu
