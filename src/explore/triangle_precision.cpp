#include "explore/triangle_precision.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <glm/geometric.hpp>

#include "geometry/triangle_tests.h"
#include "kinds/bih/bih_builder.h"
#include "kinds/bih/bih_image.h"
#include "kinds/bih/bih_kind.h"
#include "kinds/bih/fixed_arith.h"
#include "kinds/bih/grid.h"
#include "kinds/bih/projected_triangle.h"
#include "kinds/kd/kd_units.h"
#include "kinds/kd/uttm.h"
#include "rtu/golden_shell.h"

namespace rtu {
namespace {

std::vector<Ray> viewAndRandomRays(const TriangleMesh& mesh, const TriangleRaySettings& s) {
  const Aabb<double> box = meshBounds(mesh);
  std::vector<Ray> rays = viewRays(box, s.views, s.viewSize, s.viewSize);
  const std::vector<Ray> random = randomRays(box, s.randomRays, s.seed);
  rays.insert(rays.end(), random.begin(), random.end());
  return rays;
}

// Each vertex's first vertex at the same position: a mesh's seams repeat a vertex under other
// indices, and a ray through it meets the triangles of every copy.
std::vector<uint32_t> weldedVertices(const TriangleMesh& mesh) {
  std::map<std::array<double, 3>, uint32_t> first;
  std::vector<uint32_t> welded;
  for (uint32_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3& v = mesh.vertices[i];
    welded.push_back(first.emplace(std::array<double, 3>{v.x, v.y, v.z}, i).first->second);
  }
  return welded;
}

bool holds(const std::array<uint32_t, 3>& triangle, uint32_t vertex) {
  return std::find(triangle.begin(), triangle.end(), vertex) != triangle.end();
}

// Whether a ray in direction `d` through a vertex or edge that the triangles `incident` share
// crosses the surface there: every one of them faces it the same way (a mesh wound consistently).
// Otherwise the feature is on the silhouette and the ray only grazes it, where missing it is no
// hole.
bool crosses(const TriangleMesh& mesh, const std::vector<uint32_t>& incident, const glm::dvec3& d) {
  int front = 0, back = 0;
  for (uint32_t t : incident) {
    const auto& c = mesh.triangles[t];
    const glm::dvec3& v0 = mesh.vertices[c[0]];
    const double facing =
        glm::dot(glm::cross(mesh.vertices[c[1]] - v0, mesh.vertices[c[2]] - v0), d);
    front += facing < 0;
    back += facing > 0;
  }
  return front == int(incident.size()) || back == int(incident.size());
}

// The nearest hit over every triangle of a test taking (origin, direction, v0, v1, v2, limit) in
// float32; the first of equal t.
template <class Test>
std::optional<FormatHit> nearestFloat(const std::vector<Vec3<float>>& vertices,
                                      const TriangleMesh& mesh, Test&& test) {
  std::optional<FormatHit> best;
  float limit = INFINITY;
  for (uint32_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& c = mesh.triangles[i];
    const auto hit = test(vertices[c[0]], vertices[c[1]], vertices[c[2]], limit);
    if (!hit || (best && !(hit->t < limit))) continue;
    limit = hit->t;
    best = FormatHit{hit->t, i};
  }
  return best;
}

std::vector<Vec3<float>> floatVertices(const TriangleMesh& mesh) {
  std::vector<Vec3<float>> out;
  for (const glm::dvec3& v : mesh.vertices) out.push_back(Vec3<float>(v));
  return out;
}

// Seed 001's hardware space: x and y swapped (reading K4).
glm::dvec3 hardware(const glm::dvec3& v) { return {v.y, v.x, v.z}; }

std::vector<std::array<float, kUttmEntries>> unitTriangles(const TriangleMesh& mesh) {
  std::vector<std::array<float, kUttmEntries>> out;
  for (const auto& c : mesh.triangles)
    out.push_back(unpackUttm(
        packUttm(unitTriangleMatrix(hardware(mesh.vertices[c[0]]), hardware(mesh.vertices[c[1]]),
                                    hardware(mesh.vertices[c[2]])))));
  return out;
}

std::optional<FormatHit> nearestUnitTriangle(
    const std::vector<std::array<float, kUttmEntries>>& matrices, const Ray& ray,
    Division division) {
  KdRay kd;
  const glm::dvec3 o = hardware(ray.origin), d = hardware(ray.direction);
  for (int k = 0; k < 3; ++k) {
    kd.origin[k] = static_cast<float>(o[k]);
    kd.direction[k] = static_cast<float>(d[k]);
  }
  std::optional<FormatHit> best;
  for (uint32_t i = 0; i < matrices.size(); ++i) {
    const KdTriangleHit hit = intersectUnitTriangle(kd, matrices[i], division);
    // The list unit's rule: t <= the best so far, so the later of equal t wins.
    if (hit.hit && (!best || hit.t <= best->t)) best = FormatHit{hit.t, i};
  }
  return best;
}

// A fixed format's scene: the grid, the records and their BIH image, traced by the golden BIH
// traversal with the listing's kernel.
class FixedScene {
 public:
  FixedScene(const TriangleMesh& mesh, const FixedTriangleFormat& format)
      : mesh_(mesh),
        grid_(gridBoxAround(meshBounds(mesh), format), format),
        projected_(projectMesh(mesh, grid_)) {
    config_.format = format;
    if (projected_.triangles.empty()) return;  // every triangle degenerate: every ray misses
    image_ = layOut(buildBih(triangleBoxes(mesh, grid_, projected_), sceneUpper(grid_)), projected_,
                    grid_, BihIndexWidth::Wide);
    scene_ = sceneOf(decodeBihHeader(image_.words.data()));
  }

  const ProjectedMesh& projected() const { return projected_; }
  const SceneGrid& grid() const { return grid_; }

  std::optional<BihResult> trace(const GridRay& ray) const {
    if (projected_.triangles.empty()) return std::nullopt;
    GoldenShell<BihKind<>> shell(image_.memory(), config_);
    BihResult result;
    shell.run(0, BihJob{ray, scene_}, result);
    if (!result.hit) return std::nullopt;
    return result;
  }

  std::optional<FormatHit> nearest(const Ray& world) const {
    const std::optional<GridRay> ray = grid_.quantise(world);
    if (!ray) return std::nullopt;
    const std::optional<BihResult> hit = trace(*ray);
    if (!hit) return std::nullopt;
    return FormatHit{ray->worldT(hit->t), hit->primitive};
  }

  // Whether a secondary ray from the hit `hit` of `ray`, in direction `direction`, offset by
  // `offset` grid units per axis (S4 §2.1.5), hits its own triangle first.
  bool selfHit(const GridRay& ray, const BihResult& hit, const glm::dvec3& direction,
               int64_t offset) const {
    const FixedTriangleFormat& f = grid_.format();
    const int64_t highest = static_cast<int64_t>(pow2(f.n) - 1);
    const auto& corners = mesh_.triangles[hit.primitive];
    std::array<GridPoint, 3> x;
    for (int k = 0; k < 3; ++k) x[k] = grid_.quantise(mesh_.vertices[corners[k]]);
    double normal[3], dt = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      normal[k] = double(x[1][a] - x[0][a]) * double(x[2][b] - x[0][b]) -
                  double(x[1][b] - x[0][b]) * double(x[2][a] - x[0][a]);
      dt += normal[k] * direction[k];
    }
    glm::dvec3 origin;
    for (int k = 0; k < 3; ++k) {
      // h = O + t ω with one more fractional bit, rounded (half up) to the grid.
      const Int128 twice = floorShift(Int128(2) * hit.t * ray.omega[k], f.m - 1);
      const int64_t h = ray.origin[k] + static_cast<int64_t>(floorShift(twice + 1, 1));
      const int64_t moved = h + (((dt > 0) != (normal[k] < 0)) ? offset : -offset);
      origin[k] =
          grid_.box().lower[k] + double(std::clamp<int64_t>(moved, 0, highest)) / grid_.scale();
    }
    const std::optional<GridRay> secondary = grid_.quantise(Ray{origin, direction});
    if (!secondary) return false;
    const std::optional<BihResult> again = trace(*secondary);
    return again && again->primitive == hit.primitive;
  }

 private:
  const TriangleMesh& mesh_;
  SceneGrid grid_;
  ProjectedMesh projected_;
  BihImage image_;
  BihScene scene_;
  BihConfig config_;
};

std::string fixedName(const FixedTriangleFormat& f) {
  return std::string(f.listing == FixedListing::Vhdl ? "vhdl" : "c99") +
         " n=" + std::to_string(f.n) + " m=" + std::to_string(f.m) + " E=" + std::to_string(f.E) +
         " T=" + std::to_string(f.T) + " C=" + std::to_string(f.C);
}

bool sameFormat(const FixedTriangleFormat& a, const FixedTriangleFormat& b) {
  return a.n == b.n && a.m == b.m && a.E == b.E && a.T == b.T && a.C == b.C &&
         a.listing == b.listing;
}

}  // namespace

std::string TriangleFormatSpec::name() const {
  switch (arithmetic) {
    case TriangleArithmetic::Fixed: return fixedName(fixed);
    case TriangleArithmetic::UnitTriangle:
      return division == Division::Ieee ? "binary32 unit-triangle (ieee division)"
                                        : "binary32 unit-triangle (truncating division)";
    case TriangleArithmetic::MollerTrumbore32: return "float32 moller-trumbore";
    case TriangleArithmetic::Watertight32: return "float32 watertight";
  }
  return "";
}

std::string TriangleFormatSpec::structure() const {
  return arithmetic == TriangleArithmetic::Fixed ? "bih" : "all triangles";
}

TrianglePrecisionStudy::TrianglePrecisionStudy(const TriangleMesh& mesh, std::vector<Ray> traced,
                                               std::vector<AimedRay> aimed)
    : mesh_(mesh), rays_(std::move(traced)), aimed_(std::move(aimed)) {
  for (size_t i = 0; i < rays(); ++i) oracle_.push_back(closestHit(mesh_, ray(i), 0, INFINITY));
  // The triangles at each welded vertex, as welded corners.
  const std::vector<uint32_t> welded = weldedVertices(mesh_);
  std::vector<std::vector<uint32_t>> at(mesh_.vertices.size());
  for (uint32_t i = 0; i < mesh_.triangles.size(); ++i) {
    std::array<uint32_t, 3> corners;
    for (int k = 0; k < 3; ++k) corners[k] = welded[mesh_.triangles[i][k]];
    corners_.push_back(corners);
    for (uint32_t v : corners) at[v].push_back(i);
  }
  for (const AimedRay& target : aimed_) {
    std::vector<uint32_t> incident;
    for (uint32_t t : at[welded[target.a]])
      if (holds(corners_[t], welded[target.b])) incident.push_back(t);
    incident_.push_back(incident.size() >= 2 && crosses(mesh_, incident, target.ray.direction)
                            ? incident
                            : std::vector<uint32_t>{});
  }
}

TrianglePrecisionStudy::TrianglePrecisionStudy(const TriangleMesh& mesh,
                                               const TriangleRaySettings& settings)
    : TrianglePrecisionStudy(mesh, viewAndRandomRays(mesh, settings),
                             aimedFeatureRays(mesh, settings.aimedRays, settings.seed + 1)) {
  seed_ = settings.seed;
}

bool TrianglePrecisionStudy::adjacent(uint32_t a, uint32_t b) const {
  for (uint32_t v : corners_[a])
    if (holds(corners_[b], v)) return true;
  return false;
}

void TrianglePrecisionStudy::countRay(size_t i, const std::optional<FormatHit>& got,
                                      TriangleRayCounts& c) const {
  const std::optional<OracleHit>& ref = oracle_[i];
  if (i >= rays_.size()) return countAimed(i - rays_.size(), ref, got, c);
  ++c.rays;
  c.referenceHits += ref.has_value();
  c.hits += got.has_value();
  c.falseHits += got && !ref;
  c.missedHits += ref && !got;
  if (got && ref && got->triangle != ref->triangle) {
    ++c.otherTriangle;
    c.otherNotAdjacent += !adjacent(got->triangle, ref->triangle);
  }
  if (got && ref && got->triangle == ref->triangle && ref->t > 0) {
    const double error = std::abs(got->t - ref->t) / ref->t;
    ++c.sameTriangle;
    c.tErrorSum += error;
    c.tErrorMax = std::max(c.tErrorMax, error);
  }
}

void TrianglePrecisionStudy::countAimed(size_t i, const std::optional<OracleHit>& ref,
                                        const std::optional<FormatHit>& got,
                                        TriangleRayCounts& c) const {
  const std::vector<uint32_t>& incident = incident_[i];
  const auto at = [&incident](uint32_t t) {
    return std::find(incident.begin(), incident.end(), t) != incident.end();
  };
  if (!ref || incident.empty() || !at(ref->triangle)) return;
  ++c.edgeRays;
  c.holes += !got || !at(got->triangle);
}

TriangleFormatPrecision TrianglePrecisionStudy::measureFixed(const TriangleFormatSpec& spec) const {
  const FixedScene scene(mesh_, spec.fixed);
  TriangleFormatPrecision out;
  out.spec = spec;
  out.degenerate = scene.projected().degenerate;
  out.clamped = scene.projected().clampedTriangles;
  out.counts = count([&scene](const Ray& ray) { return scene.nearest(ray); });
  // Secondary rays from every hit, in directions drawn as random rays' are.
  std::vector<std::pair<GridRay, BihResult>> hits;
  for (size_t i = 0; i < rays(); ++i) {
    const std::optional<GridRay> gridRay = scene.grid().quantise(ray(i));
    if (!gridRay) continue;
    if (const std::optional<BihResult> hit = scene.trace(*gridRay))
      hits.push_back({*gridRay, *hit});
  }
  const std::vector<Ray> directions = randomRays(scene.grid().box(), hits.size(), seed_ + 2);
  SelfIntersection self;
  for (size_t i = 0; i < hits.size(); ++i) {
    ++self.secondaryRays;
    const glm::dvec3& d = directions[i].direction;
    self.selfHitsOffset += scene.selfHit(hits[i].first, hits[i].second, d, 2);
    self.selfHitsNoOffset += scene.selfHit(hits[i].first, hits[i].second, d, 0);
  }
  out.self = self;
  return out;
}

TriangleFormatPrecision TrianglePrecisionStudy::measure(const TriangleFormatSpec& spec) const {
  if (spec.arithmetic == TriangleArithmetic::Fixed) return measureFixed(spec);
  TriangleFormatPrecision out;
  out.spec = spec;
  const std::vector<Vec3<float>> vertices = floatVertices(mesh_);
  const auto single = [](const Ray& ray, Vec3<float>& o, Vec3<float>& d) {
    o = Vec3<float>(ray.origin);
    d = Vec3<float>(ray.direction);
  };
  switch (spec.arithmetic) {
    case TriangleArithmetic::UnitTriangle: {
      const auto matrices = unitTriangles(mesh_);
      out.counts =
          count([&](const Ray& ray) { return nearestUnitTriangle(matrices, ray, spec.division); });
      break;
    }
    case TriangleArithmetic::MollerTrumbore32:
      out.counts = count([&](const Ray& ray) {
        Vec3<float> o, d;
        single(ray, o, d);
        return nearestFloat(vertices, mesh_, [&](auto& a, auto& b, auto& c, float limit) {
          return mollerTrumbore(o, d, a, b, c, 0.0f, limit);
        });
      });
      break;
    default:
      out.counts = count([&](const Ray& ray) {
        Vec3<float> o, d;
        single(ray, o, d);
        const ShearedRay<float> sheared(o, d);
        return nearestFloat(vertices, mesh_, [&](auto& a, auto& b, auto& c, float limit) {
          return watertight(sheared, a, b, c, 0.0f, limit);
        });
      });
  }
  return out;
}

std::vector<TriangleFormatSpec> sweepRows(const TriangleSweep& sweep) {
  std::vector<TriangleFormatSpec> rows{TriangleFormatSpec{}};
  const std::pair<const char*, std::pair<const std::vector<int>*, int FixedTriangleFormat::*>>
      parameters[] = {{"n", {&sweep.n, &FixedTriangleFormat::n}},
                      {"m", {&sweep.m, &FixedTriangleFormat::m}},
                      {"E", {&sweep.E, &FixedTriangleFormat::E}},
                      {"T", {&sweep.T, &FixedTriangleFormat::T}},
                      {"C", {&sweep.C, &FixedTriangleFormat::C}}};
  for (const auto& [name, values] : parameters)
    for (int value : *values.first) {
      TriangleFormatSpec row;
      row.fixed.*values.second = value;
      row.swept = name;
      validateFixedTriangleFormat(row.fixed);
      if (!sameFormat(row.fixed, kC99Format)) rows.push_back(row);
    }
  TriangleFormatSpec vhdl;
  vhdl.fixed = kVhdlFormat;
  rows.push_back(vhdl);
  for (const Division division : {Division::Ieee, Division::TowardZero}) {
    TriangleFormatSpec row;
    row.arithmetic = TriangleArithmetic::UnitTriangle;
    row.division = division;
    rows.push_back(row);
  }
  for (const TriangleArithmetic a :
       {TriangleArithmetic::MollerTrumbore32, TriangleArithmetic::Watertight32}) {
    TriangleFormatSpec row;
    row.arithmetic = a;
    rows.push_back(row);
  }
  return rows;
}

TriangleMesh stressTriangle(double width) {
  TriangleMesh mesh;
  const double side = width / std::sqrt(2.0);
  mesh.vertices = {{0, 0, 0}, {1, 1, 1}, {0.5 + side, 0.5 - side, 0.5}};
  mesh.triangles = {{0, 1, 2}};
  return mesh;
}

}  // namespace rtu
