#include "kinds/bvh/bvh_image.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "base/float_bits.h"

namespace rtu {
namespace {

constexpr uint64_t kMaxNodes = uint64_t{1} << 31;       // indices 0 .. 2^31 - 1 in bits 30:0
constexpr uint64_t kMaxRefs = (uint64_t{1} << 31) - 1;  // a root leaf's numPrim in bits 30:0
constexpr uint64_t kMaxTriangles = uint64_t{1} << 32;   // indices in one word

void checkCount(uint64_t count, uint64_t limit, const std::string& what, const std::string& why) {
  const std::string exceeded = capacityExceeded(count, limit, what, why);
  if (!exceeded.empty()) throw BvhCapacityError(exceeded);
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
          floatBits(vertexCoordinate(mesh.vertices[mesh.triangles[index][corner]][k]));
  words[9] = index;
}

}  // namespace

BvhHeader bvhSections(uint64_t nodes, uint64_t refs, uint64_t triangles) {
  if (nodes == 0) throw BvhCapacityError("a tree needs a root node");
  checkCount(nodes, kMaxNodes, "nodes", "child indices have 31 bits");
  checkCount(refs, kMaxRefs, "references", "a leaf's count has 31 bits");
  checkCount(triangles, kMaxTriangles, "triangles", "references are 32-bit indices");
  BvhHeader header;
  std::string error;
  if (!placeSections(nodes, kBvhNodeWords, refs, triangles, kBvhTriangleWords, header, error))
    throw BvhCapacityError(error);
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
  std::copy(tree.refs.begin(), tree.refs.end(), words + header.listBase);
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
  writeSections(header, words.data());
  return words;
}

BvhHeader decodeHeader(const uint32_t* words) {
  BvhHeader header;
  static_cast<ImageSections&>(header) = readSections(words);
  return header;
}

std::array<uint32_t, kBvhNodeWords> encodeNode(const BvhNode& node) {
  std::array<uint32_t, kBvhNodeWords> words{};
  for (int k = 0; k < 3; ++k) {
    words[k] = floatBits(node.box.lower[k]);
    words[3 + k] = floatBits(node.box.upper[k]);
  }
  words[6] = node.leftOrFirst;
  words[7] = (node.leaf ? kBvhLeafBit : 0) | node.rightOrCount;
  return words;
}

BvhNode decodeNode(const uint32_t* words) {
  BvhNode node;
  for (int k = 0; k < 3; ++k) {
    node.box.lower[k] = bitsToFloat(words[k]);
    node.box.upper[k] = bitsToFloat(words[3 + k]);
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
  return *record("reference", index, header_.listCount, refAddress(index), 1);
}

BvhTriangle BvhImageView::triangle(uint32_t index) const {
  const uint32_t* words =
      record("triangle", index, header_.triangleCount, triangleAddress(index), kBvhTriangleWords);
  BvhTriangle triangle;
  for (int corner = 0; corner < 3; ++corner)
    for (int k = 0; k < 3; ++k) triangle.vertices[corner][k] = bitsToFloat(words[3 * corner + k]);
  triangle.source = words[9];
  return triangle;
}

}  // namespace rtu
