#include "kinds/kd/trayracer_scene.h"

#include <stdexcept>

#include "base/float_bits.h"
#include "kinds/kd/truncated_float.h"

namespace rtu {
namespace {

// The field widths of a format's nodes and ids.
struct Layout {
  int nodeBits, splitBits, childBits, indexBits, countBits, idBits;
};
constexpr Layout kNarrow{48, 28, 16, 16, 6, 16};
constexpr Layout kWide{64, 32, 28, 28, 12, 32};
const Layout& layoutOf(TrayRacerFormat format) {
  return format == TrayRacerFormat::Narrow ? kNarrow : kWide;
}

constexpr uint32_t kLeafAxis = 3;
// R1 (dump_kdtree): PBRT's axis 0 (world x) is written 01, 1 (world y) 00: hardware x is world y.
constexpr uint32_t kHardwareAxis[3] = {1, 0, 2};

uint64_t mask(int bits) { return bits == 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1; }

void checkFits(uint64_t value, int bits, const std::string& what) {
  if (value > mask(bits))
    throw std::invalid_argument(
        what + " " + std::to_string(value) + " does not fit its " + std::to_string(bits) +
        "-bit field; use the wide format (accel.index = wide, --index wide)");
}

uint64_t encode(const TrayRacerNode& node, const Layout& l) {
  const int top = l.nodeBits - 2;
  if (node.leaf) {
    checkFits(node.listIndex, l.indexBits, "list index");
    checkFits(node.count, l.countBits, "leaf triangle count");
    return uint64_t(kLeafAxis) << top | uint64_t(node.listIndex) << (top - l.indexBits) |
           uint64_t(node.count) << (top - l.indexBits - l.countBits);
  }
  checkFits(node.high, l.childBits, "child node id");
  const uint64_t split = node.splitBits >> (32 - l.splitBits);
  return uint64_t(node.axis) << top | split << (top - l.splitBits) | uint64_t(node.high) << 2 |
         uint64_t(node.lowEmpty) << 1 | uint64_t(node.highEmpty);
}

class Writer {
 public:
  void section(uint32_t words) { word(words); }
  void word(uint32_t w) { bits(w, 32); }
  void bits(uint64_t value, int count) {
    for (int shift = count - 8; shift >= 0; shift -= 8) bytes_.push_back(uint8_t(value >> shift));
  }
  void pad() {
    while (bytes_.size() % 4 != 0) bytes_.push_back(0);
  }
  std::vector<uint8_t> take() { return std::move(bytes_); }

 private:
  std::vector<uint8_t> bytes_;
};

uint32_t wordsFor(size_t items, int bits) { return uint32_t((items * bits + 31) / 32); }

class Reader {
 public:
  explicit Reader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
  // The next section's word count and where its payload starts.
  uint32_t section(const char* name) {
    name_ = name;
    const uint32_t words = uint32_t(bits(32));
    if (at_ + size_t(words) * 4 > bytes_.size())
      fail("holds " + std::to_string(words) + " words, past the file's end");
    end_ = at_ + size_t(words) * 4;
    return words;
  }
  uint64_t bits(int count) {
    if (at_ + size_t(count / 8) > bytes_.size()) fail("ends early");
    uint64_t value = 0;
    for (int i = 0; i < count / 8; ++i) value = value << 8 | bytes_[at_++];
    return value;
  }
  // The payload's unread bytes must be zero padding.
  void endSection() {
    for (; at_ < end_; ++at_)
      if (bytes_[at_] != 0) fail("has a nonzero pad byte at offset " + std::to_string(at_));
  }
  void finish() const {
    if (at_ != bytes_.size()) throw std::runtime_error("Tray Racer scene: bytes after the box");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(std::string("Tray Racer scene: ") + name_ + " section " + what);
  }

 private:
  const std::vector<uint8_t>& bytes_;
  size_t at_ = 0, end_ = 0;
  const char* name_ = "";
};

TrayRacerNode decode(uint64_t value, const Layout& l, size_t number, const Reader& reader) {
  const int top = l.nodeBits - 2;
  TrayRacerNode node;
  node.axis = uint32_t(value >> top);
  if (node.axis == kLeafAxis) {
    node.leaf = true;
    node.listIndex = uint32_t(value >> (top - l.indexBits) & mask(l.indexBits));
    node.count = uint32_t(value >> (top - l.indexBits - l.countBits) & mask(l.countBits));
    node.axis = 0;
    if ((value & mask(top - l.indexBits - l.countBits)) != 0)
      reader.fail("node " + std::to_string(number) + ": a leaf's low bits are not zero");
    return node;
  }
  node.splitBits = uint32_t(value >> (top - l.splitBits) & mask(l.splitBits)) << (32 - l.splitBits);
  node.high = uint32_t(value >> 2 & mask(l.childBits));
  node.lowEmpty = value >> 1 & 1;
  node.highEmpty = value & 1;
  return node;
}

uint32_t shadeField(double value, int bits) {
  return truncatedBits(static_cast<float>(value), bits);
}

}  // namespace

glm::dvec3 trayRacerNormal(const TrayRacerShade& shade) {
  // The record's 160 bits run from word 0's most significant bit: ambient r, g, b at bits 0, 24
  // and 48, the normal's x, y, z at 72, 96 and 120.
  const auto field = [&shade](int first) {
    uint32_t value = 0;
    for (int bit = first; bit < first + kFloat24Bits; ++bit)
      value = value << 1 | ((shade[bit / 32] >> (31 - bit % 32)) & 1);
    return static_cast<double>(paddedFloat(value, kFloat24Bits));
  };
  return {field(72), field(96), field(120)};
}

bool TrayRacerNode::operator==(const TrayRacerNode& o) const {
  return leaf == o.leaf && axis == o.axis && splitBits == o.splitBits && high == o.high &&
         lowEmpty == o.lowEmpty && highEmpty == o.highEmpty && listIndex == o.listIndex &&
         count == o.count;
}

TrayRacerScene makeTrayRacerScene(const KdBuild& build, const std::vector<glm::dvec3>& corners,
                                  const std::vector<glm::dvec3>& normals,
                                  const TrayRacerMaterial& material, KdMatrixColumn column) {
  TrayRacerScene scene;
  for (const KdBuildNode& b : build.nodes) {
    TrayRacerNode node;
    node.leaf = b.leaf;
    if (b.leaf) {
      node.listIndex = b.listIndex;
      node.count = b.count;
    } else {
      node.axis = kHardwareAxis[b.axis];
      node.splitBits = floatBits(b.split);
      node.high = b.above;
      node.lowEmpty = b.belowEmpty;
      node.highEmpty = b.aboveEmpty;
    }
    scene.nodes.push_back(node);
  }
  scene.lists = build.lists;
  for (size_t i = 0; i + 2 < corners.size(); i += 3)
    scene.uttms.push_back(
        packUttm(unitTriangleMatrix(toHardwareSpace(corners[i]), toHardwareSpace(corners[i + 1]),
                                    toHardwareSpace(corners[i + 2]), column)));
  // Five words: 3 + 3 float24 then a float16, 20 bytes; the fields straddle words.
  for (const glm::dvec3& n : normals) {
    Writer w;
    for (int k = 0; k < 3; ++k) w.bits(shadeField(material.ambient[k], kFloat24Bits), 24);
    for (int k = 0; k < 3; ++k) w.bits(shadeField(n[k], kFloat24Bits), 24);
    w.bits(shadeField(material.specular, kFloat16Bits), 16);
    const std::vector<uint8_t> bytes = w.take();
    TrayRacerShade shade{};
    for (size_t b = 0; b < bytes.size(); ++b)
      shade[b / 4] |= uint32_t(bytes[b]) << (24 - 8 * (b % 4));
    scene.shades.push_back(shade);
  }
  const Aabb<float>& box = build.bounds;
  scene.box = {box.lower.y, box.lower.x, box.lower.z, box.upper.y, box.upper.x, box.upper.z};
  return scene;
}

std::vector<uint8_t> writeTrayRacerScene(const TrayRacerScene& scene, TrayRacerFormat format) {
  const Layout& l = layoutOf(format);
  Writer w;
  w.section(wordsFor(scene.nodes.size(), l.nodeBits));
  for (const TrayRacerNode& node : scene.nodes) w.bits(encode(node, l), l.nodeBits);
  w.pad();
  w.section(wordsFor(scene.lists.size(), l.idBits));
  for (uint32_t id : scene.lists) {
    checkFits(id, l.idBits, "triangle id");
    w.bits(id, l.idBits);
  }
  w.pad();
  w.section(uint32_t(scene.uttms.size() * kUttmWords));
  for (const UttmWords& uttm : scene.uttms)
    for (uint32_t word : uttm) w.word(word);
  w.section(uint32_t(scene.shades.size() * 5));
  for (const TrayRacerShade& shade : scene.shades)
    for (uint32_t word : shade) w.word(word);
  w.section(6);
  for (float bound : scene.box) w.word(floatBits(bound));
  return w.take();
}

TrayRacerScene readTrayRacerScene(const std::vector<uint8_t>& bytes, TrayRacerFormat format) {
  const Layout& l = layoutOf(format);
  Reader r(bytes);
  TrayRacerScene scene;
  const size_t nodeCount = size_t(r.section("node")) * 32 / l.nodeBits;
  for (size_t i = 0; i < nodeCount; ++i) scene.nodes.push_back(decode(r.bits(l.nodeBits), l, i, r));
  r.endSection();
  // The list words hold S or S + 1 ids (a zero pad); the leaves say which.
  const size_t slots = size_t(r.section("list")) * 32 / l.idBits;
  size_t entries = 0;
  for (const TrayRacerNode& node : scene.nodes)
    if (node.leaf) entries += node.count;
  if (entries > slots || slots - entries >= size_t(32 / l.idBits))
    r.fail("has room for " + std::to_string(slots) + " ids, the leaves count " +
           std::to_string(entries));
  for (size_t i = 0; i < entries; ++i) scene.lists.push_back(uint32_t(r.bits(l.idBits)));
  r.endSection();
  const uint32_t uttmWords = r.section("UTTM");
  if (uttmWords % kUttmWords != 0) r.fail("is not 9 words per triangle");
  scene.uttms.resize(uttmWords / kUttmWords);
  for (UttmWords& uttm : scene.uttms)
    for (uint32_t& word : uttm) word = uint32_t(r.bits(32));
  const uint32_t shadeWords = r.section("colour");
  if (shadeWords != scene.uttms.size() * 5) r.fail("is not 5 words per triangle");
  scene.shades.resize(scene.uttms.size());
  for (TrayRacerShade& shade : scene.shades)
    for (uint32_t& word : shade) word = uint32_t(r.bits(32));
  if (r.section("box") != 6) r.fail("is not 6 words");
  for (float& bound : scene.box) bound = bitsToFloat(uint32_t(r.bits(32)));
  r.finish();
  return scene;
}

std::vector<std::string> trayRacerCapacityWarnings(const TrayRacerScene& scene) {
  uint32_t perLeaf = 0;
  for (const TrayRacerNode& node : scene.nodes)
    if (node.leaf && node.count > perLeaf) perLeaf = node.count;
  std::vector<std::string> warnings;
  const auto check = [&warnings](size_t value, size_t limit, const std::string& what) {
    if (value > limit)
      warnings.push_back(what + ": " + std::to_string(value) + " exceeds the Tray Racer's " +
                         std::to_string(limit));
  };
  check(scene.nodes.size(), 4096, "k-d nodes (tcache)");
  check(scene.lists.size(), 16384, "list entries (lcache)");
  check(scene.uttms.size(), 1024, "triangles (icache)");
  check(perLeaf, 63, "triangles in one leaf (6-bit count)");
  return warnings;
}

}  // namespace rtu
