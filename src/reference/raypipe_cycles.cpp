// The per-cycle reference of seed 001's ray pipe (raypipe_cycles.h): the cycle's order of units.
#include "reference/raypipe_cycles.h"

#include "reference/raypipe_top.h"

namespace rtu {
namespace raypipe_ref {

void Pipe::step(size_t& exited, size_t& written) {
  // The arbiters' offers: every input's valid is a register or a FIFO's flag.
  u_.offerAll(now_);
  for (size_t i = 0; i < u_.trav.size(); ++i) travToSsStall_[i] = u_.travToSsStall(i);
  listToSsStall_ = u_.listToSsStall();
  sintToSsStall_ = !u_.sintSs.empty() && u_.restWrite[2].full();
  shaderReturn(exited, written);
  listUnit();
  intersection();
  traversal();
  shortStack();
  sceneIntersection();
  shaderIssueAndPrg();
  tick();
}

void Pipe::tick() { u_.tick(now_); }

}  // namespace raypipe_ref

RaypipeCycleRun runRaypipeCycles(const RaypipeConfig& config, const KdImage& image,
                                 const std::vector<RaypipeCycleRay>& rays,
                                 const RaypipeCycleOptions& options) {
  const RaypipePixelWriter& writer = options.writer;
  config.validate();
  if (writer.vgaPhase < 0) throw std::invalid_argument("the VGA phase must not be negative");
  if (options.cyclesSinceReset < 0)
    throw std::invalid_argument("the cycles since reset must not be negative");
  raypipe_ref::Pipe pipe(config, image, rays, options);
  return pipe.run();
}

}  // namespace rtu