#pragma once
// The k-d golden traversal's agreement with the independent oracle (geometry/triangle_oracle.h),
// shared by test_kd_oracle.cpp (the spider and R1's elephant) and the k-d kind's fixture
// (tests/kinds/kd_fixture.h, its checkOracle in test_kd_kind.cpp). KdAgreement (docs/triangles.md,
// "k-d tree (seed 001)"): both miss or hit the same triangle; or both hit within 4 float32 ulp of
// the same t (a shared edge or vertex); or a disagreement explained by the stored matrices: the
// ray crosses a disputed triangle's plane within `bound` of its edge in unit-triangle coordinates
// (crossing below); or by the build, a triangle the oracle hits that no leaf lists or that lies
// flat on a split plane; anything else is unexplained and must not occur.

#include <algorithm>
#include <cmath>
#include <optional>
#include <ostream>
#include <utility>
#include <vector>

#include "base/float_bits.h"
#include "geometry/ray.h"
#include "geometry/triangle_mesh.h"
#include "geometry/triangle_oracle.h"
#include "kinds/kd/kd_kind.h"
#include "rtu/golden_shell.h"

namespace rtu {

inline std::vector<glm::dvec3> cornersOf(const TriangleMesh& mesh) {
  std::vector<glm::dvec3> corners;
  for (const auto& triangle : mesh.triangles)
    for (uint32_t index : triangle) corners.push_back(mesh.vertices[index]);
  return corners;
}

// The mesh in hardware space, as the UTTMs hold it (up to their rounding).
inline TriangleMesh inHardwareSpace(TriangleMesh mesh) {
  for (auto& v : mesh.vertices) v = toHardwareSpace(v);
  return mesh;
}

inline KdRay hardwareRay(const Ray& world) {
  const glm::vec3 o(toHardwareSpace(world.origin)), d(toHardwareSpace(world.direction));
  return KdRay{{o.x, o.y, o.z}, {d.x, d.y, d.z}, false};
}

inline Ray asDouble(const KdRay& ray) {
  const auto v = [](const std::array<float, 3>& a) { return glm::dvec3(a[0], a[1], a[2]); };
  return Ray{v(ray.origin), v(ray.direction)};
}

// `explained`: near an edge. The seed's build also loses triangles the oracle hits: those in no
// leaf's list (`unlisted`: the edge order END before START at equal positions keeps a triangle
// flat on the chosen split's axis and at its position out of both children) and those flat on a
// split plane (`onSplit`: listed on one side only, so a ray crossing the plane
// at the triangle meets it only if it visits that side, which TRAV's rounded t_mid decides).
struct KdAgreement {
  int same = 0, ties = 0, explained = 0, unlisted = 0, onSplit = 0, unexplained = 0;
  int disagreements() const { return explained + unlisted + onSplit + unexplained; }
};

inline std::ostream& operator<<(std::ostream& out, const KdAgreement& a) {
  return out << "same " << a.same << " ties " << a.ties << " explained " << a.explained
             << " unlisted " << a.unlisted << " on a split " << a.onSplit << " unexplained "
             << a.unexplained;
}

// Why the build loses each triangle, if it does.
enum class KdLoss : uint8_t { None, Unlisted, OnSplit };

inline bool flatOnSplit(const TriangleMesh& hardware, uint32_t triangle,
                        const TrayRacerScene& scene) {
  const auto& ids = hardware.triangles[triangle];
  for (uint32_t axis = 0; axis < 3; ++axis) {
    const float plane = static_cast<float>(hardware.vertices[ids[0]][axis]);
    bool flat = true;
    for (uint32_t id : ids) flat = flat && static_cast<float>(hardware.vertices[id][axis]) == plane;
    if (!flat) continue;
    // Within a narrow split's truncation (19 fraction bits kept) of a split on that axis.
    for (const TrayRacerNode& node : scene.nodes)
      if (!node.leaf && node.axis == axis &&
          std::abs(bitsToFloat(node.splitBits) - plane) <= std::abs(plane) * 0x1.0p-18f)
        return true;
  }
  return false;
}

inline std::vector<KdLoss> lossesOf(const TriangleMesh& hardware, const TrayRacerScene& scene) {
  std::vector<KdLoss> losses(scene.uttms.size(), KdLoss::Unlisted);
  for (uint32_t id : scene.lists) losses.at(id) = KdLoss::None;
  for (uint32_t i = 0; i < losses.size(); ++i)
    if (losses[i] == KdLoss::None && flatOnSplit(hardware, i, scene)) losses[i] = KdLoss::OnSplit;
  return losses;
}

// Where the ray crosses the triangle's plane, in its exact unit-triangle coordinates, and how far
// the INT unit's u and v may stray from it. The stored entries are float24: each within
// 2^-15 + 2^-24 of its double value relatively (RNE to float, then 8 bits truncated), and each of
// INT's binary32 operations adds at most 2^-24 of a partial sum no greater than the sum of the
// magnitudes of its terms; so, to first order, with e = 2^-14 (above 2^-15 + 7 * 2^-24):
//   o'_r, d'_r stray by e S_r, e D_r (S_r = sum_j |m_rj o_j| + |t_r|, D_r = sum_j |m_rj d_j|);
//   t = o'_z / -d'_z by e t (S_z / |o'_z| + D_z / |d'_z|) + 2^-24 t;
//   u = o'_x + d'_x t by e (S_x + t D_x) + |d'_x| (the error of t) + 2^-23 (|d'_x t| + |u|).
// The bound is the sum of u's and v's, as u + v is tested too.
struct KdCrossing {
  double margin =
      INFINITY;  // |min(u, v, 1 - u - v)|: inside, to the nearest edge; outside, how far
  double bound = 0;
};

inline KdCrossing kdCrossing(const TriangleMesh& hardware, uint32_t triangle, const Ray& ray) {
  const auto& ids = hardware.triangles[triangle];
  const UnitTriangleMatrix m = unitTriangleMatrix(
      hardware.vertices[ids[0]], hardware.vertices[ids[1]], hardware.vertices[ids[2]]);
  std::array<double, 3> o{}, d{}, s{}, ds{};
  for (int r = 0; r < 3; ++r) {
    o[r] = m.t[r];
    s[r] = std::abs(m.t[r]);
    for (int j = 0; j < 3; ++j) {
      o[r] += m.m[r][j] * ray.origin[j];
      d[r] += m.m[r][j] * ray.direction[j];
      s[r] += std::abs(m.m[r][j] * ray.origin[j]);
      ds[r] += std::abs(m.m[r][j] * ray.direction[j]);
    }
  }
  const double t = -o[2] / d[2];
  if (!std::isfinite(t)) return KdCrossing{};
  const double e = 0x1.0p-14;
  const double tError =
      e * std::abs(t) * (s[2] / std::abs(o[2]) + ds[2] / std::abs(d[2])) + 0x1.0p-24 * std::abs(t);
  KdCrossing c;
  double bary[2];
  for (int r = 0; r < 2; ++r) {
    bary[r] = o[r] + d[r] * t;
    c.bound += e * (s[r] + std::abs(t) * ds[r]) + std::abs(d[r]) * tError +
               0x1.0p-23 * (std::abs(d[r] * t) + std::abs(bary[r]));
  }
  c.margin = std::abs(std::min({bary[0], bary[1], 1 - bary[0] - bary[1]}));
  return c;
}

// A scene's image checked against the oracle over `mesh`, the scene's triangles in world space in
// the scene's order.
class KdOracleCheck {
 public:
  KdOracleCheck(TriangleMesh mesh, const TrayRacerScene& scene)
      : mesh_(std::move(mesh)),
        hardware_(inHardwareSpace(mesh_)),
        image_(layOutKd(scene)),
        losses_(lossesOf(hardware_, scene)),
        sections_(sectionsOf(decodeKdHeader(image_.words.data()))) {}

  const TriangleMesh& mesh() const { return mesh_; }
  const KdImage& image() const { return image_; }
  KdJob job(const Ray& world) const { return KdJob{hardwareRay(world), sections_}; }

  KdAgreement compare(const std::vector<Ray>& rays) const {
    GoldenShell<KdKind> shell(image_.memory(), KdTraversalConfig{});
    KdAgreement agreement;
    for (const Ray& world : rays) {
      const KdJob j = job(world);
      KdResult result;
      shell.run(0, j, result);
      classify(j.ray, result, agreement);
    }
    return agreement;
  }

  // A golden result of the hardware-space ray `hardwareRay` against the oracle's answer.
  void classify(const KdRay& hardwareRay, const KdResult& result, KdAgreement& agreement) const {
    const Ray ray = asDouble(hardwareRay);
    classify(result, closestHit(hardware_, ray, 0, INFINITY), ray, agreement);
  }

 private:
  void classify(const KdResult& result, const std::optional<OracleHit>& oracle, const Ray& ray,
                KdAgreement& agreement) const {
    if (result.hit == oracle.has_value() && (!oracle || result.primitive == oracle->triangle)) {
      ++agreement.same;
    } else if (result.hit && oracle && std::abs(result.t - oracle->t) <= 4 * ulp(oracle->t)) {
      ++agreement.ties;
    } else if ((result.hit && nearEdge(result.primitive, ray)) ||
               (oracle && nearEdge(oracle->triangle, ray))) {
      ++agreement.explained;
    } else if (oracle && losses_[oracle->triangle] == KdLoss::Unlisted) {
      ++agreement.unlisted;
    } else if (oracle && losses_[oracle->triangle] == KdLoss::OnSplit) {
      ++agreement.onSplit;
    } else {
      ++agreement.unexplained;
    }
  }
  bool nearEdge(uint32_t triangle, const Ray& ray) const {
    const KdCrossing c = kdCrossing(hardware_, triangle, ray);
    return c.margin <= c.bound;
  }
  static double ulp(double t) {
    const float f = static_cast<float>(t);
    return std::nextafter(f, INFINITY) - f;
  }

  TriangleMesh mesh_, hardware_;
  KdImage image_;
  std::vector<KdLoss> losses_;
  KdSections sections_;
};

}  // namespace rtu
