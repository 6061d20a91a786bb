#include "kinds/svo/procedural_scenes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "kinds/svo/svo_builder.h"

namespace rtu {

namespace {

// splitmix64's finaliser: every input bit affects every output bit.
uint64_t mix(uint64_t value) {
  value += 0x9E3779B97F4A7C15ull;
  value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ull;
  value = (value ^ (value >> 27)) * 0x94D049BB133111EBull;
  return value ^ (value >> 31);
}

uint64_t hash(uint64_t a, uint64_t b, uint64_t c, uint64_t seed) {
  return mix(mix(mix(mix(seed) ^ a) ^ b) ^ c);
}

// The voxel indices [first, last] a node covers along one axis.
struct VoxelSpan {
  uint32_t first;
  uint32_t last;
};

// Voxel centres are dyadic rationals, exact in a double, and so are their squares and the
// quantised terrain heights: every comparison below is exact, so a node's answer agrees bit for
// bit with the answers for the voxels inside it.
class Scene : public VoxelSource {
 public:
  explicit Scene(int depth) : depth_(depth) {}
  int depth() const override { return depth_; }

 protected:
  VoxelSpan span(uint32_t cell, int level) const {
    const int shift = depth_ - level;
    return {cell << shift, ((cell + 1) << shift) - 1};
  }
  double centre(uint32_t voxel) const { return std::ldexp(2.0 * voxel + 1.0, -depth_) - 1.0; }

  const int depth_;
};

// Solid where inner <= |centre| <= outer: a ball, or a shell when inner > 0.
class RadialBand : public Scene {
 public:
  RadialBand(int depth, double inner, double outer)
      : Scene(depth), inner2_(squared(std::max(inner, 0.0))), outer2_(squared(outer)) {}

  // The node's voxel centres lie in a box; its nearest and farthest points from the origin
  // bound their distances.
  Occupancy classify(const OctreeNode& node) const override {
    double nearest2 = 0;
    double farthest2 = 0;
    for (uint32_t cell : {node.x, node.y, node.z}) {
      const VoxelSpan voxels = span(cell, node.level);
      const double lo = centre(voxels.first);
      const double hi = centre(voxels.last);
      nearest2 += squared(lo > 0 ? lo : hi < 0 ? -hi : 0.0);
      farthest2 += squared(std::max(-lo, hi));
    }
    if (farthest2 < inner2_ || nearest2 > outer2_) return Occupancy::Empty;
    if (nearest2 >= inner2_ && farthest2 <= outer2_) return Occupancy::Full;
    return Occupancy::Mixed;
  }

 private:
  static double squared(double value) { return value * value; }

  const double inner2_;
  const double outer2_;
};

// The cube is the sponge's unit cube. Iteration i removes the points whose i-th ternary digits
// are 1 on at least two axes; there are as many iterations as leave the smallest holes at least a
// voxel wide, so each of them holds voxel centres.
//
// A node's voxel centres are a product of three index ranges, so per axis it is enough to know at
// which iterations some centre in the range has digit 1 (`some`) and at which all of them have
// (`all`): the node lies in a hole when two axes share a bit of `all`, and avoids every hole when
// no two axes share a bit of `some`. These masks are tabled for every node of every level.
class Menger : public Scene {
 public:
  explicit Menger(int depth) : Scene(depth), masks_(depth + 1) {
    int iterations = 0;
    for (uint64_t power = 3; power <= (uint64_t{1} << depth); power *= 3) ++iterations;
    tabulateVoxels(iterations);
    for (int level = depth - 1; level >= 0; --level) tabulateLevel(level);
  }

  Occupancy classify(const OctreeNode& node) const override {
    const std::vector<MiddleDigits>& level = masks_[node.level];
    const MiddleDigits& x = level[node.x];
    const MiddleDigits& y = level[node.y];
    const MiddleDigits& z = level[node.z];
    if (onTwoAxes(x.all, y.all, z.all) != 0) return Occupancy::Empty;
    if (onTwoAxes(x.some, y.some, z.some) == 0) return Occupancy::Full;
    return Occupancy::Mixed;
  }

 private:
  // Bit i-1 stands for iteration i.
  struct MiddleDigits {
    uint16_t some;
    uint16_t all;
  };

  static uint16_t onTwoAxes(uint16_t x, uint16_t y, uint16_t z) {
    return static_cast<uint16_t>((x & y) | (y & z) | (z & x));
  }

  // The voxel centre (2v+1)/2^(depth+1) times 3^i, rounded down, ends in its i-th ternary digit.
  void tabulateVoxels(int iterations) {
    std::vector<MiddleDigits>& voxels = masks_[depth_];
    voxels.resize(size_t{1} << depth_);
    for (uint32_t v = 0; v < voxels.size(); ++v) {
      uint16_t middle = 0;
      uint64_t power = 1;
      for (int i = 0; i < iterations; ++i) {
        power *= 3;
        if (((2 * uint64_t{v} + 1) * power >> (depth_ + 1)) % 3 == 1) middle |= 1u << i;
      }
      voxels[v] = {middle, middle};
    }
  }

  void tabulateLevel(int level) {
    const std::vector<MiddleDigits>& finer = masks_[level + 1];
    std::vector<MiddleDigits>& cells = masks_[level];
    cells.resize(size_t{1} << level);
    for (size_t i = 0; i < cells.size(); ++i) {
      const MiddleDigits& lower = finer[2 * i];
      const MiddleDigits& upper = finer[2 * i + 1];
      cells[i] = {static_cast<uint16_t>(lower.some | upper.some),
                  static_cast<uint16_t>(lower.all & upper.all)};
    }
  }

  std::vector<std::vector<MiddleDigits>> masks_;  // per level, per cell index along an axis
};

// Solid where the centre's y is at most its column's height. Heights are sampled from fractal
// value noise on a grid of up to 2^kMaxSampleLevel cells per side and interpolated bilinearly to
// column centres. A bilinear patch takes its extremes at the corners of any rectangle, so the
// height range of the columns inside one cell comes from four columns; a min/max pyramid over the
// cells answers bigger nodes.
class Terrain : public Scene {
 public:
  Terrain(int depth, uint64_t seed)
      : Scene(depth), seed_(seed), sampleLevel_(std::min(depth, kMaxSampleLevel)) {
    sampleHeights();
    buildPyramid();
  }

  Occupancy classify(const OctreeNode& node) const override {
    const HeightRange heights = heightRange(node);
    const VoxelSpan ys = span(node.y, node.level);
    if (centre(ys.last) <= heights.lowest) return Occupancy::Full;
    if (centre(ys.first) > heights.highest) return Occupancy::Empty;
    return Occupancy::Mixed;
  }

 private:
  static constexpr int kMaxSampleLevel = 10;  // 1025^2 samples, a 22 MB pyramid
  static constexpr int kOctaves = 6;
  static constexpr double kLatticeCells = 4;  // value-noise cells across the cube, first octave
  static constexpr double kBaseHeight = -0.3;
  static constexpr double kRelief = 0.5;  // heights stay in kBaseHeight +- kRelief

  struct HeightRange {
    double lowest;
    double highest;
  };

  uint32_t samplesPerSide() const { return (1u << sampleLevel_) + 1; }
  double sample(uint32_t i, uint32_t j) const { return samples_[size_t{j} * samplesPerSide() + i]; }

  void sampleHeights() {
    const uint32_t side = samplesPerSide();
    samples_.resize(size_t{side} * side);
    for (uint32_t j = 0; j < side; ++j)
      for (uint32_t i = 0; i < side; ++i)
        samples_[size_t{j} * side + i] =
            quantised(height(std::ldexp(i, -sampleLevel_), std::ldexp(j, -sampleLevel_)));
  }

  // Fractal value noise at unit coordinates (u, v) in [0,1]^2.
  double height(double u, double v) const {
    double sum = 0;
    double amplitude = 1;
    double amplitudes = 0;
    for (int octave = 0; octave < kOctaves; ++octave) {
      const double cells = kLatticeCells * (1 << octave);
      sum += amplitude * valueNoise(u * cells, v * cells, octave);
      amplitudes += amplitude;
      amplitude *= 0.5;
    }
    return kBaseHeight + kRelief * sum / amplitudes;
  }

  double valueNoise(double u, double v, int octave) const {
    const double iu = std::floor(u);
    const double iv = std::floor(v);
    const double wu = smoothstep(u - iu);
    const double wv = smoothstep(v - iv);
    const auto lattice = [&](double du, double dv) {
      const uint64_t bits = hash(static_cast<uint64_t>(iu + du), static_cast<uint64_t>(iv + dv),
                                 static_cast<uint64_t>(octave), seed_);
      return std::ldexp(static_cast<double>(bits >> 11), -52) - 1.0;  // [-1, 1)
    };
    return lerp(lerp(lattice(0, 0), lattice(1, 0), wu), lerp(lattice(0, 1), lattice(1, 1), wu), wv);
  }

  static double smoothstep(double t) { return t * t * (3 - 2 * t); }
  static double lerp(double a, double b, double t) { return a + (b - a) * t; }
  // Multiples of 2^-20 keep bilinear interpolation at dyadic column centres exact.
  static double quantised(double value) {
    return std::ldexp(std::round(std::ldexp(value, 20)), -20);
  }

  // Bilinear interpolation in the column's sample cell, at the column's centre.
  double columnHeight(uint32_t x, uint32_t z) const {
    const int shift = depth_ - sampleLevel_;
    const uint32_t columnsPerCell = 1u << shift;
    const uint32_t i = x >> shift;
    const uint32_t j = z >> shift;
    const double u = std::ldexp(2.0 * (x & (columnsPerCell - 1)) + 1, -shift - 1);
    const double v = std::ldexp(2.0 * (z & (columnsPerCell - 1)) + 1, -shift - 1);
    return lerp(lerp(sample(i, j), sample(i + 1, j), u),
                lerp(sample(i, j + 1), sample(i + 1, j + 1), u), v);
  }

  // Height range of the columns in xs x zs, which lie in one sample cell.
  HeightRange columnRange(VoxelSpan xs, VoxelSpan zs) const {
    const std::array<double, 4> corners = {
        columnHeight(xs.first, zs.first), columnHeight(xs.last, zs.first),
        columnHeight(xs.first, zs.last), columnHeight(xs.last, zs.last)};
    const auto [lowest, highest] = std::minmax_element(corners.begin(), corners.end());
    return {*lowest, *highest};
  }

  // pyramid_[level] holds the height range of every node column at that level, for levels up to
  // the sample level; finer nodes lie inside one cell.
  void buildPyramid() {
    pyramid_.resize(sampleLevel_ + 1);
    const uint32_t cells = 1u << sampleLevel_;
    std::vector<HeightRange>& base = pyramid_[sampleLevel_];
    base.resize(size_t{cells} * cells);
    for (uint32_t j = 0; j < cells; ++j)
      for (uint32_t i = 0; i < cells; ++i)
        base[size_t{j} * cells + i] = columnRange(span(i, sampleLevel_), span(j, sampleLevel_));
    for (int level = sampleLevel_ - 1; level >= 0; --level) reducePyramidLevel(level);
  }

  void reducePyramidLevel(int level) {
    const uint32_t side = 1u << level;
    const std::vector<HeightRange>& finer = pyramid_[level + 1];
    std::vector<HeightRange>& coarser = pyramid_[level];
    coarser.resize(size_t{side} * side);
    for (uint32_t j = 0; j < side; ++j) {
      for (uint32_t i = 0; i < side; ++i) {
        HeightRange range = finer[size_t{2 * j} * 2 * side + 2 * i];
        for (uint32_t child = 1; child < 4; ++child) {
          const HeightRange& part = finer[size_t{2 * j + child / 2} * 2 * side + 2 * i + child % 2];
          range = {std::min(range.lowest, part.lowest), std::max(range.highest, part.highest)};
        }
        coarser[size_t{j} * side + i] = range;
      }
    }
  }

  HeightRange heightRange(const OctreeNode& node) const {
    if (node.level > sampleLevel_)
      return columnRange(span(node.x, node.level), span(node.z, node.level));
    return pyramid_[node.level][size_t{node.z} * (1u << node.level) + node.x];
  }

  const uint64_t seed_;
  const int sampleLevel_;
  std::vector<double> samples_;
  std::vector<std::vector<HeightRange>> pyramid_;
};

// A room (issue 30's interior-like scene): floor, ceiling, back and side walls an eighth of the
// cube thick, the front (z = -1) open, with a table on four legs, a chair, a cabinet, shelves, two
// pillars and three balls. Open so that a camera just outside the root cube sees the inside: the
// SVO traversal finds the first voxel from where a ray's line enters the cube, so a camera inside
// it would see what lies behind it. Solid where the voxel centre lies in one of its boxes or
// balls; every bound is a multiple of 1/32, so every comparison is exact, as above.
class Room : public Scene {
 public:
  explicit Room(int depth) : Scene(depth) {}

  // Full when one part holds every voxel centre of the node, Empty when none holds any.
  Occupancy classify(const OctreeNode& node) const override {
    std::array<Range, 3> centres;
    const std::array<uint32_t, 3> cells = {node.x, node.y, node.z};
    for (int axis = 0; axis < 3; ++axis) {
      const VoxelSpan voxels = span(cells[axis], node.level);
      centres[axis] = {centre(voxels.first), centre(voxels.last)};
    }
    bool some = false;
    for (const Part& part : kParts) {
      const Occupancy occupancy = part.classify(centres);
      if (occupancy == Occupancy::Full) return Occupancy::Full;
      some = some || occupancy == Occupancy::Mixed;
    }
    return some ? Occupancy::Mixed : Occupancy::Empty;
  }

 private:
  struct Range {
    double lo, hi;
  };
  // A box (radius 0) or a ball (radius > 0, centred on box.lo).
  struct Part {
    std::array<Range, 3> box;
    double radius;

    Occupancy classify(const std::array<Range, 3>& centres) const {
      return radius > 0 ? classifyBall(centres) : classifyBox(centres);
    }
    Occupancy classifyBox(const std::array<Range, 3>& centres) const {
      bool inside = true;
      for (int axis = 0; axis < 3; ++axis) {
        if (centres[axis].hi < box[axis].lo || centres[axis].lo > box[axis].hi)
          return Occupancy::Empty;
        inside = inside && centres[axis].lo >= box[axis].lo && centres[axis].hi <= box[axis].hi;
      }
      return inside ? Occupancy::Full : Occupancy::Mixed;
    }
    Occupancy classifyBall(const std::array<Range, 3>& centres) const {
      double nearest2 = 0;
      double farthest2 = 0;
      for (int axis = 0; axis < 3; ++axis) {
        const double lo = centres[axis].lo - box[axis].lo;
        const double hi = centres[axis].hi - box[axis].lo;
        nearest2 += square(lo > 0 ? lo : hi < 0 ? -hi : 0.0);
        farthest2 += square(std::max(-lo, hi));
      }
      if (nearest2 > square(radius)) return Occupancy::Empty;
      return farthest2 <= square(radius) ? Occupancy::Full : Occupancy::Mixed;
    }
    static double square(double value) { return value * value; }
  };
  static constexpr Part box(Range x, Range y, Range z) { return {{x, y, z}, 0}; }
  static constexpr Part ball(double x, double y, double z, double radius) {
    return {{Range{x, x}, Range{y, y}, Range{z, z}}, radius};
  }

  static constexpr double kWall = 0.875;  // the walls' inner faces
  static const std::array<Part, 23> kParts;
};

const std::array<Room::Part, 23> Room::kParts = {{
    box({-1, 1}, {-1, -kWall}, {-1, 1}),                        // floor
    box({-1, 1}, {kWall, 1}, {-1, 1}),                          // ceiling
    box({-1, -kWall}, {-1, 1}, {-1, 1}),                        // left wall
    box({kWall, 1}, {-1, 1}, {-1, 1}),                          // right wall
    box({-1, 1}, {-1, 1}, {kWall, 1}),                          // back wall
    box({-0.375, 0.375}, {-0.375, -0.3125}, {0.125, 0.625}),    // table top
    box({-0.375, -0.3125}, {-kWall, -0.375}, {0.125, 0.1875}),  // its legs
    box({0.3125, 0.375}, {-kWall, -0.375}, {0.125, 0.1875}),
    box({-0.375, -0.3125}, {-kWall, -0.375}, {0.5625, 0.625}),
    box({0.3125, 0.375}, {-kWall, -0.375}, {0.5625, 0.625}),
    box({-0.125, 0.125}, {-0.5625, -0.5}, {-0.125, 0.0625}),       // chair seat
    box({-0.125, 0.125}, {-0.5, -0.1875}, {-0.125, -0.0625}),      // its back
    box({-0.125, -0.0625}, {-kWall, -0.5625}, {-0.125, -0.0625}),  // two of its legs
    box({0.0625, 0.125}, {-kWall, -0.5625}, {-0.125, -0.0625}),
    box({-kWall, -0.625}, {-kWall, 0.25}, {0.25, 0.75}),  // cabinet
    box({-0.5, 0.25}, {-0.25, -0.21875}, {0.75, kWall}),  // shelves
    box({-0.5, 0.25}, {0, 0.03125}, {0.75, kWall}),
    box({-0.5, 0.25}, {0.25, 0.28125}, {0.75, kWall}),
    box({0.5, 0.625}, {-kWall, kWall}, {0.5, 0.625}),  // pillars
    box({0.5, 0.625}, {-kWall, kWall}, {-0.25, -0.125}),
    ball(0, 0.625, 0.375, 0.125),          // lamp
    ball(0.125, -0.1875, 0.375, 0.125),    // ball on the table
    ball(-0.375, -0.6875, -0.25, 0.1875),  // ball on the floor
}};

// Each voxel is solid with probability 1/32. Nodes above the voxels are left to the builder.
class WhiteNoise : public Scene {
 public:
  WhiteNoise(int depth, uint64_t seed) : Scene(depth), seed_(seed) {}

  Occupancy classify(const OctreeNode& node) const override {
    if (node.level < depth_) return Occupancy::Mixed;
    return hash(node.x, node.y, node.z, seed_) >> 59 == 0 ? Occupancy::Full : Occupancy::Empty;
  }

 private:
  const uint64_t seed_;
};

constexpr double kSphereRadius = 0.8;
constexpr double kShellWall = 0.1;

struct SceneEntry {
  const char* name;
  std::unique_ptr<VoxelSource> (*make)(int depth, uint64_t seed);
};

const std::array<SceneEntry, 6> kScenes = {{
    {"sphere",
     [](int depth, uint64_t) -> std::unique_ptr<VoxelSource> {
       return std::make_unique<RadialBand>(depth, 0.0, kSphereRadius);
     }},
    {"shell",
     [](int depth, uint64_t) -> std::unique_ptr<VoxelSource> {
       const double wall = std::max(kShellWall, 2 * std::ldexp(2.0, -depth));
       return std::make_unique<RadialBand>(depth, kSphereRadius - wall, kSphereRadius);
     }},
    {"menger",
     [](int depth, uint64_t) -> std::unique_ptr<VoxelSource> {
       return std::make_unique<Menger>(depth);
     }},
    {"terrain",
     [](int depth, uint64_t seed) -> std::unique_ptr<VoxelSource> {
       return std::make_unique<Terrain>(depth, seed);
     }},
    {"noise",
     [](int depth, uint64_t seed) -> std::unique_ptr<VoxelSource> {
       return std::make_unique<WhiteNoise>(depth, seed);
     }},
    {"room",
     [](int depth, uint64_t) -> std::unique_ptr<VoxelSource> {
       return std::make_unique<Room>(depth);
     }},
}};

std::string knownNames() {
  std::string names;
  for (const std::string& name : proceduralSceneNames())
    names += (names.empty() ? "" : ", ") + name;
  return names;
}

}  // namespace

const std::vector<std::string>& proceduralSceneNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const SceneEntry& scene : kScenes) list.emplace_back(scene.name);
    return list;
  }();
  return names;
}

std::unique_ptr<VoxelSource> makeProceduralScene(const std::string& name, int depth,
                                                 uint64_t seed) {
  const auto scene = std::find_if(kScenes.begin(), kScenes.end(),
                                  [&](const SceneEntry& entry) { return name == entry.name; });
  if (scene == kScenes.end())
    throw std::invalid_argument("unknown procedural scene '" + name + "' (known: " + knownNames() +
                                ")");
  if (depth < 1 || depth > kMaxSvoDepth)
    throw std::invalid_argument("procedural scene depth must be 1 to " +
                                std::to_string(kMaxSvoDepth) + ", got " + std::to_string(depth));
  return scene->make(depth, seed);
}

}  // namespace rtu
