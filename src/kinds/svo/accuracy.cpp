#include "kinds/svo/accuracy.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "kinds/svo/reference_model.h"

namespace rtu {

std::string AccuracyReport::describe() const {
  char text[512];
  std::snprintf(
      text, sizeof text,
      "agreement   %.4f %% of %zu rays compared (t within %g), %zu float64 hits\n"
      "overflows   %zu rays overflowed the stack (flagged, not compared)\n"
      "mismatches  %zu hit/miss, %zu t beyond tolerance (%zu edge hits agree on t, not face)\n"
      "t error     mean %.3g, max %.3g (where both hit)\n"
      "cost        fixed %llu, float64 %llu cycles in total\n",
      100.0 * agreement(), compared(), tTolerance, referenceHits, stackOverflows, hitMismatches,
      tOutliers, edgeHits, meanTError, maxTError, static_cast<unsigned long long>(fixedCost),
      static_cast<unsigned long long>(referenceCost));
  return text;
}

AccuracyReport measureAccuracy(const WordMemory& memory, uint32_t root,
                               const std::vector<Ray>& rays, const GoldenConfig& config,
                               double epsilon, double tTolerance) {
  GoldenModel golden(memory, config);
  ReferenceModel reference(memory, epsilon);
  AccuracyReport report;
  report.tTolerance = tTolerance;
  report.rays = rays.size();
  double errorSum = 0.0;
  size_t bothHit = 0;
  for (const Ray& ray : rays) {
    const TraversalResult fixed = golden.trace(makeTValueRecord(0, ray, root, epsilon));
    const ReferenceResult exact = reference.trace(ray, root);
    report.fixedCost += fixed.cost;
    report.referenceCost += exact.cost;
    report.referenceHits += exact.hit;
    if (fixed.stackOverflow) {
      ++report.stackOverflows;
    } else if (fixed.hit != exact.hit) {
      ++report.hitMismatches;
    } else if (fixed.hit) {
      const double error = std::abs(config.format.toDouble(fixed.tHit) - exact.tHit);
      report.maxTError = std::max(report.maxTError, error);
      errorSum += error;
      ++bothHit;
      if (error > tTolerance)
        ++report.tOutliers;
      else if (fixed.normal[exact.normalAxis] == 0)
        ++report.edgeHits;
    }
  }
  report.meanTError = bothHit ? errorSum / bothHit : 0.0;
  return report;
}

size_t countDifferences(const std::vector<TraversalResult>& a,
                        const std::vector<TraversalResult>& b) {
  if (a.size() != b.size()) throw std::invalid_argument("result sets differ in size");
  size_t differences = 0;
  for (size_t i = 0; i < a.size(); ++i) differences += a[i] != b[i];
  return differences;
}

}  // namespace rtu
