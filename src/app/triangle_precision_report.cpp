#include "app/triangle_precision_report.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "base/output_file.h"
#include "explore/accel_build.h"
#include "explore/exploration_run.h"

namespace rtu {
namespace {

struct StudyRow {
  std::string study;  // "mesh" or "stress"
  TriangleFormatPrecision result;
};

void printTable(const std::string& title, const std::vector<TriangleFormatPrecision>& results,
                std::ostream& out) {
  out << title << "\n";
  char line[320];
  std::snprintf(line, sizeof line, "%-46s %5s %9s %9s %9s %9s %10s %10s %7s %6s %9s %9s\n",
                "format", "swept", "false hit", "missed", "other tri", "not adj.", "t rel mean",
                "t rel max", "edge", "holes", "self ±2", "self 0");
  out << line;
  for (const TriangleFormatPrecision& p : results) {
    const TriangleRayCounts& c = p.counts;
    const std::string offset = p.self ? std::to_string(p.self->selfHitsOffset) : "-";
    const std::string none = p.self ? std::to_string(p.self->selfHitsNoOffset) : "-";
    std::snprintf(
        line, sizeof line, "%-46s %5s %9llu %9llu %9llu %9llu %10.3g %10.3g %7llu %6llu %9s %9s\n",
        p.spec.name().c_str(), p.spec.swept.c_str(), (unsigned long long)c.falseHits,
        (unsigned long long)c.missedHits, (unsigned long long)c.otherTriangle,
        (unsigned long long)c.otherNotAdjacent, c.tErrorMean(), c.tErrorMax,
        (unsigned long long)c.edgeRays, (unsigned long long)c.holes, offset.c_str(), none.c_str());
    out << line;
  }
}

void writeCsv(const std::vector<StudyRow>& rows, const std::string& meshName,
              const std::string& path) {
  OutputFile output(path);
  std::ostream& file = output.stream();
  file << csvLine({"study",
                   "mesh",
                   "format",
                   "arithmetic",
                   "structure",
                   "swept",
                   "n",
                   "m",
                   "E",
                   "T",
                   "C",
                   "rays",
                   "reference_hits",
                   "hits",
                   "false_hits",
                   "missed_hits",
                   "other_triangle",
                   "other_not_adjacent",
                   "t_rel_error_mean",
                   "t_rel_error_max",
                   "edge_rays",
                   "holes",
                   "degenerate",
                   "clamped",
                   "secondary_rays",
                   "self_hits_offset",
                   "self_hits_no_offset"});
  for (const StudyRow& row : rows) {
    const TriangleFormatPrecision& p = row.result;
    const bool fixed = p.spec.arithmetic == TriangleArithmetic::Fixed;
    const auto field = [fixed](int value) { return fixed ? std::to_string(value) : ""; };
    const auto self = [&p](uint64_t SelfIntersection::*member) {
      return p.self ? std::to_string((*p.self).*member) : "";
    };
    const TriangleRayCounts& c = p.counts;
    static const char* const kArithmetic[] = {"fixed", "binary32_unit_triangle",
                                              "float32_moller_trumbore", "float32_watertight"};
    file << csvLine({row.study,
                     row.study == "stress" ? "stress triangle" : meshName,
                     p.spec.name(),
                     kArithmetic[static_cast<int>(p.spec.arithmetic)],
                     p.spec.structure(),
                     p.spec.swept,
                     field(p.spec.fixed.n),
                     field(p.spec.fixed.m),
                     field(p.spec.fixed.E),
                     field(p.spec.fixed.T),
                     field(p.spec.fixed.C),
                     std::to_string(c.rays),
                     std::to_string(c.referenceHits),
                     std::to_string(c.hits),
                     std::to_string(c.falseHits),
                     std::to_string(c.missedHits),
                     std::to_string(c.otherTriangle),
                     std::to_string(c.otherNotAdjacent),
                     precisionFigure(c.tErrorMean()),
                     precisionFigure(c.tErrorMax),
                     std::to_string(c.edgeRays),
                     std::to_string(c.holes),
                     fixed ? std::to_string(p.degenerate) : "",
                     fixed ? std::to_string(p.clamped) : "",
                     self(&SelfIntersection::secondaryRays),
                     self(&SelfIntersection::selfHitsOffset),
                     self(&SelfIntersection::selfHitsNoOffset)});
  }
  output.commit();
}

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("precision --triangles: " + what);
}

// Every row's format checked before any tracing, naming the flag of a refused value.
std::vector<TriangleFormatSpec> checkedRows(const TriangleSweep& sweep) {
  try {
    return sweepRows(sweep);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(std::string("precision --triangles (--n, --m, --E, --T, --C): ") +
                                error.what());
  }
}

}  // namespace

void runTrianglePrecision(const TrianglePrecisionOptions& options, RunConfig settings) {
  const TriangleRaySettings& r = options.rays;
  require(r.views >= 0 && r.viewSize >= 0, "--views and --view-size must not be negative");
  require(options.stressWidth >= 0, "--stress-size must not be negative");
  require(r.randomRays + r.aimedRays + size_t(r.views) * r.viewSize > 0, "no rays to trace");
  const std::vector<TriangleFormatSpec> rows = checkedRows(options.sweep);
  settings.accel.dropBadTriangles = options.dropBadTriangles;
  const TriangleScene scene = loadSceneTriangles(settings);
  const TrianglePrecisionStudy study(scene.mesh, r);
  std::vector<StudyRow> all;
  std::vector<TriangleFormatPrecision> results;
  for (const TriangleFormatSpec& spec : rows) {
    results.push_back(study.measure(spec));
    all.push_back({"mesh", results.back()});
  }
  printTable(scene.name + ", " + std::to_string(scene.mesh.triangles.size()) + " triangles, " +
                 std::to_string(study.rays() - study.aimedRays()) + " rays and " +
                 std::to_string(study.aimedRays()) +
                 " aimed at vertices and edges, against float64 watertight",
             results, std::cout);
  const int stressHeight = options.stressWidth * 3 / 4;
  if (stressHeight > 0) {
    // S4 §2.5.1: the thin triangle two pixels wide in a view of the box at the seed's resolution.
    const TriangleMesh stress =
        stressTriangle(2 * std::sqrt(3.0) / static_cast<double>(options.stressWidth));
    const TrianglePrecisionStudy stressStudy(
        stress, viewRays(meshBounds(stress), 1, options.stressWidth, stressHeight), {});
    std::vector<TriangleFormatPrecision> stressResults;
    for (const TriangleFormatSpec& spec : rows)
      if (spec.swept.empty()) {
        stressResults.push_back(stressStudy.measure(spec));
        all.push_back({"stress", stressResults.back()});
      }
    printTable("stress triangle (S4 2.5.1), " + std::to_string(stressStudy.rays()) + " rays",
               stressResults, std::cout);
  }
  if (!options.csv.empty()) {
    writeCsv(all, scene.name, options.csv);
    std::cout << "wrote " << options.csv << "\n";
  }
}

std::string precisionFigure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace rtu
