#include "kinds/bvh/bvh_image.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace rtu {
namespace {

// The header's words 0-10, in order.
constexpr std::array<uint32_t BvhHeader::*, 11> kHeaderFields = {
    &BvhHeader::magic,         &BvhHeader::kind,      &BvhHeader::version,
    &BvhHeader::flags,         &BvhHeader::nodeBase,  &BvhHeader::nodeCount,
    &BvhHeader::refBase,       &BvhHeader::refCount,  &BvhHeader::triangleBase,
    &BvhHeader::triangleCount, &BvhHeader::totalWords};

constexpr uint64_t kMaxNodes = uint64_t{1} << 31;        // indices 0 .. 2^31 - 1 in bits 30:0
constexpr uint64_t kMaxRefs = (uint64_t{1} << 31) - 1;   // a root leaf's numPrim in bits 30:0
constexpr uint64_t kMaxTriangles = uint64_t{1} << 32;    // indices in one word
constexpr uint64_t kMaxWords = (uint64_t{1} << 32) - 1;  // the size in header word 10

uint64_t alignedToAccess(uint64_t words) { return (words + 3) / 4 * 4; }

void checkCount(uint64_t count, uint64_t limit, const std::string& what, const std::string& why) {
  if (count > limit)
    throw BvhCapacityError(std::to_string(count) + " " + what + ", more than " +
                           std::to_string(limit) + " (" + why + ")");
}

uint32_t bits(float value) {
  uint32_t word;
  std::memcpy(&word, &value, sizeof word);
  return word;
}

float toFloat(uint32_t word) {
  float value;
  std::memcpy(&value, &word, sizeof value);
  return value;
}

// Rounded to nearest; refused beyond float32's range, where the conversion is undefined.
float vertexCoordinate(double value) {
  if (!(std::abs(value) <= std::numeric_limits<float>::max()))
    throw BvhCapacityError("a vertex coordinate (" + std::to_string(value) +
                           ") is beyond float32's range");
  return static_cast<float>(value);
}

BvhNode nodeOf(const BuildNode& node) {
  if (node.leaf()) return {roundOutward(node.box), true, node.first, node.count};
  return {roundOutward(node.box), false, node.left, node.right};
}

void writeTriangle(const TriangleMesh& mesh, uint32_t index, uint32_t* words) {
  for (int corner = 0; corner < 3; ++corner)
    for (int k = 0; k < 3; ++k)
      words[3 * corner + k] =
          bits(vertexCoordinate(mesh.vertices[mesh.triangles[index][corner]][k]));
  words[9] = index;
}

}  // namespace

BvhHeader bvhSections(uint64_t nodes, uint64_t refs, uint64_t triangles) {
  if (nodes == 0) throw BvhCapacityError("a tree needs a root node");
  checkCount(nodes, kMaxNodes, "nodes", "child indices have 31 bits");
  checkCount(refs, kMaxRefs, "references", "a leaf's count has 31 bits");
  checkCount(triangles, kMaxTriangles, "triangles", "references are 32-bit indices");
  const uint64_t refBase = kBvhHeaderWords + kBvhNodeWords * nodes;
  const uint64_t triangleBase = alignedToAccess(refBase + refs);
  const uint64_t totalWords = triangleBase + kBvhTriangleWords * triangles;
  checkCount(totalWords, kMaxWords, "words", "word addresses have 32 bits");
  BvhHeader header;
  header.nodeBase = kBvhHeaderWords;
  header.nodeCount = static_cast<uint32_t>(nodes);
  header.refBase = static_cast<uint32_t>(refBase);
  header.refCount = static_cast<uint32_t>(refs);
  header.triangleBase = static_cast<uint32_t>(triangleBase);
  header.triangleCount = static_cast<uint32_t>(triangles);
  header.totalWords = static_cast<uint32_t>(totalWords);
  return header;
}

BvhImage layOutNodes(const BuildTree& tree, uint64_t triangles) {
  const BvhHeader header = bvhSections(tree.nodes.size(), tree.refs.size(), triangles);
  BvhImage image;
  image.words.assign(header.totalWords, 0);
  uint32_t* words = image.words.data();
  const auto headerWords = encodeHeader(header);
  std::copy(headerWords.begin(), headerWords.end(), words);
  for (size_t i = 0; i < tree.nodes.size(); ++i) {
    const auto nodeWords = encodeNode(nodeOf(tree.nodes[i]));
    std::copy(nodeWords.begin(), nodeWords.end(), words + header.nodeBase + kBvhNodeWords * i);
  }
  std::copy(tree.refs.begin(), tree.refs.end(), words + header.refBase);
  return image;
}

BvhImage layOut(const BuildTree& tree, const TriangleMesh& mesh) {
  BvhImage image = layOutNodes(tree, mesh.triangles.size());
  const BvhHeader header = decodeHeader(image.words.data());
  for (uint32_t t = 0; t < header.triangleCount; ++t)
    writeTriangle(mesh, t, image.words.data() + header.triangleBase + kBvhTriangleWords * t);
  return image;
}

std::array<uint32_t, kBvhHeaderWords> encodeHeader(const BvhHeader& header) {
  std::array<uint32_t, kBvhHeaderWords> words{};
  for (size_t i = 0; i < kHeaderFields.size(); ++i) words[i] = header.*kHeaderFields[i];
  return words;
}

BvhHeader decodeHeader(const uint32_t* words) {
  BvhHeader header;
  for (size_t i = 0; i < kHeaderFields.size(); ++i) header.*kHeaderFields[i] = words[i];
  return header;
}

std::array<uint32_t, kBvhNodeWords> encodeNode(const BvhNode& node) {
  std::array<uint32_t, kBvhNodeWords> words{};
  for (int k = 0; k < 3; ++k) {
    words[k] = bits(node.box.lower[k]);
    words[3 + k] = bits(node.box.upper[k]);
  }
  words[6] = node.leftOrFirst;
  words[7] = (node.leaf ? kBvhLeafBit : 0) | node.rightOrCount;
  return words;
}

BvhNode decodeNode(const uint32_t* words) {
  BvhNode node;
  for (int k = 0; k < 3; ++k) {
    node.box.lower[k] = toFloat(words[k]);
    node.box.upper[k] = toFloat(words[3 + k]);
  }
  node.leaf = (words[7] & kBvhLeafBit) != 0;
  node.leftOrFirst = words[6];
  node.rightOrCount = words[7] & ~kBvhLeafBit;
  return node;
}

BvhImageView::BvhImageView(const std::vector<uint32_t>& words) : words_(words) {
  if (words.size() < kBvhHeaderWords)
    throw std::out_of_range("BVH image: " + std::to_string(words.size()) +
                            " words, fewer than a header's " + std::to_string(kBvhHeaderWords));
  header_ = decodeHeader(words.data());
}

const uint32_t* BvhImageView::record(const char* section, uint32_t index, uint32_t count,
                                     uint64_t address, uint32_t size) const {
  if (index >= count)
    throw std::out_of_range(std::string("BVH image: ") + section + " " + std::to_string(index) +
                            " of " + std::to_string(count));
  if (address + size > words_.size())
    throw std::out_of_range(std::string("BVH image: ") + section + " " + std::to_string(index) +
                            " at word " + std::to_string(address) + " is beyond the image's " +
                            std::to_string(words_.size()) + " words");
  return words_.data() + address;
}

BvhNode BvhImageView::node(uint32_t index) const {
  return decodeNode(record("node", index, header_.nodeCount, nodeAddress(index), kBvhNodeWords));
}

uint32_t BvhImageView::ref(uint32_t index) const {
  return *record("reference", index, header_.refCount, refAddress(index), 1);
}

BvhTriangle BvhImageView::triangle(uint32_t index) const {
  const uint32_t* words =
      record("triangle", index, header_.triangleCount, triangleAddress(index), kBvhTriangleWords);
  BvhTriangle triangle;
  for (int corner = 0; corner < 3; ++corner)
    for (int k = 0; k < 3; ++k) triangle.vertices[corner][k] = toFloat(words[3 * corner + k]);
  triangle.source = words[9];
  return triangle;
}

}  // namespace rtu
