#include "kinds/svo/reference_model.h"

namespace rtu {

ReferenceModel::ReferenceModel(WordMemory memory, double epsilon, int stackFrames)
    : memory_(memory), epsilon_(epsilon), core_(Float64Arith{}, stackFrames) {}

ReferenceResult ReferenceModel::trace(const Ray& ray, uint32_t root) {
  const RayParameters<double> parameters = computeRayParameters<double>(ray, epsilon_);
  core_.start(parameters.t0, parameters.t1, parameters.a, root);
  runToCompletion(core_, memory_);
  core_.finish();
  ReferenceResult result;
  result.hit = core_.hit();
  result.tHit = core_.hit() ? core_.tHit() : 0.0;
  result.normalAxis = core_.normalAxis();
  result.cost = core_.cost();
  result.stackOverflow = core_.stackOverflow();
  if (result.hit) result.voxel = core_.hitVoxel();
  return result;
}

}  // namespace rtu
