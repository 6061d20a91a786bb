#include "kinds/svo/precision.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kinds/svo/golden_model.h"
#include "kinds/svo/reference_model.h"

namespace rtu {
namespace {

double percentile99(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t k = (values.size() * 99) / 100;
  std::nth_element(values.begin(),
                   values.begin() + static_cast<std::ptrdiff_t>(std::min(k, values.size() - 1)),
                   values.end());
  return values[std::min(k, values.size() - 1)];
}

FormatPrecision compare(const WordMemory& memory, const PrecisionStudy& study,
                        const FixedFormat& format, const std::vector<ReferenceResult>& reference) {
  GoldenModel golden(memory, GoldenConfig{format, study.conversion, kMaxStackFrames});
  FormatPrecision p;
  p.format = format;
  p.rays = study.rays.size();
  p.verdicts.reserve(p.rays);
  const double step = std::ldexp(1.0, -format.fractionBits);
  std::vector<double> errors;
  double errorSum = 0.0, cost = 0.0, referenceCost = 0.0;
  for (size_t i = 0; i < study.rays.size(); ++i) {
    const Ray& ray = study.rays[i];
    const TraversalResult fixed = golden.trace(makeTValueRecord(0, ray, study.root, study.epsilon));
    const ReferenceResult& exact = reference[i];
    cost += fixed.cost;
    referenceCost += exact.cost;
    p.referenceHits += exact.hit;
    p.overflowRays += fixed.stackOverflow;
    p.tOverflowRays += fixed.tOverflow;
    p.belowResolutionRays += fixed.belowResolution;
    PrecisionVerdict verdict = PrecisionVerdict::BothMiss;
    if (fixed.hit && !exact.hit) {
      verdict = PrecisionVerdict::FalseHit;
      ++p.falseHits;
    } else if (!fixed.hit && exact.hit) {
      verdict = PrecisionVerdict::MissedHit;
      ++p.missedHits;
    } else if (fixed.hit) {
      const double t = format.toDouble(fixed.tHit);
      const double error = std::abs(t - exact.tHit) / step;
      errors.push_back(error);
      errorSum += error;
      const bool sameVoxel = golden.lastHitVoxel() == exact.voxel;
      verdict = sameVoxel ? PrecisionVerdict::Agree : PrecisionVerdict::DifferentVoxel;
      p.differentVoxels += !sameVoxel;
    }
    p.wrongUnflagged += verdict != PrecisionVerdict::BothMiss &&
                        verdict != PrecisionVerdict::Agree && !fixed.tOverflow &&
                        !fixed.belowResolution;
    p.verdicts.push_back(verdict);
  }
  if (!errors.empty()) {
    p.tErrorMeanSteps = errorSum / static_cast<double>(errors.size());
    p.tErrorMaxSteps = *std::max_element(errors.begin(), errors.end());
    p.tErrorP99Steps = percentile99(std::move(errors));
  }
  if (p.rays > 0) {
    p.meanCost = cost / static_cast<double>(p.rays);
    p.referenceMeanCost = referenceCost / static_cast<double>(p.rays);
  }
  return p;
}

}  // namespace

double FormatPrecision::costChange() const {
  return referenceMeanCost > 0.0 ? meanCost / referenceMeanCost - 1.0 : 0.0;
}

std::vector<FormatPrecision> measurePrecision(const WordMemory& memory, const PrecisionStudy& study,
                                              const std::vector<FixedFormat>& formats) {
  for (const FixedFormat& format : formats) format.validate();
  ReferenceModel referenceModel(memory, study.epsilon);
  std::vector<ReferenceResult> reference;
  reference.reserve(study.rays.size());
  for (const Ray& ray : study.rays) reference.push_back(referenceModel.trace(ray, study.root));
  std::vector<FormatPrecision> results;
  for (const FixedFormat& format : formats)
    results.push_back(compare(memory, study, format, reference));
  return results;
}

namespace {

// `format`, validated; the error names `text`.
FixedFormat checked(const std::string& text, const FixedFormat& format) {
  try {
    format.validate();
  } catch (const std::invalid_argument& invalid) {
    throw std::invalid_argument("format '" + text + "': " + invalid.what());
  }
  return format;
}

bool isValid(const FixedFormat& format) {
  try {
    format.validate();
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

// A bare "A.B": the one reading that gives a format, QA.B or A bits with B of them fraction.
FixedFormat bareFormat(const std::string& text, int first, int second) {
  const FixedFormat integerFraction{first + second, second}, totalFraction{first, second};
  if (isValid(integerFraction) && isValid(totalFraction))
    throw std::invalid_argument("format '" + text + "' is ambiguous: write " +
                                totalFraction.describe() + " or " + integerFraction.describe());
  return checked(text, isValid(integerFraction) ? integerFraction : totalFraction);
}

}  // namespace

FixedFormat parseFixedFormat(const std::string& text) {
  const std::string error = "format '" + text + "': write QI.F (e.g. Q16.16: 32 bits)";
  const bool q = !text.empty() && (text[0] == 'Q' || text[0] == 'q');
  const std::string body = q ? text.substr(1) : text;
  const size_t dot = body.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == body.size() ||
      body.find_first_not_of("0123456789.") != std::string::npos ||
      body.find('.', dot + 1) != std::string::npos)
    throw std::invalid_argument(error);
  int first = 0, second = 0;
  try {
    first = std::stoi(body.substr(0, dot));
    second = std::stoi(body.substr(dot + 1));
  } catch (const std::exception&) {
    throw std::invalid_argument(error);
  }
  if (first > 64 || second > 64) throw std::invalid_argument(error);  // no int overflow below
  return q ? checked(text, {first + second, second}) : bareFormat(text, first, second);
}

}  // namespace rtu
