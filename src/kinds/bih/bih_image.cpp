#include "kinds/bih/bih_image.h"

#include <algorithm>

namespace rtu {
namespace {

// The header's own words 11-14, in order.
constexpr std::array<uint32_t BihHeader::*, 4> kOwnFields = {
    &BihHeader::upperX, &BihHeader::upperY, &BihHeader::upperZ, &BihHeader::format};
constexpr int kFieldBits = 6;
constexpr uint32_t kVhdlBit = uint32_t{1} << 30;

void checkCount(uint64_t count, uint64_t limit, const std::string& what, const std::string& why) {
  const std::string exceeded = capacityExceeded(count, limit, what, why);
  if (!exceeded.empty()) throw BihCapacityError(exceeded);
}

void warnAbove(std::vector<std::string>& warnings, uint64_t count, uint64_t limit,
               const std::string& what) {
  if (count > limit)
    warnings.push_back("BIH image: " + std::to_string(count) + " " + what +
                       ", more than the seed's " + std::to_string(limit) +
                       " (Listing A.3: 4x1Kx36 block RAM with the stack at 992-1023)");
}

BihNode nodeOf(const BihBuildNode& node) {
  if (node.leaf) return {kBihLeafAxis, node.index, node.count, 0};
  return {node.axis, node.index, static_cast<uint32_t>(node.clip0),
          static_cast<uint32_t>(node.clip1)};
}

uint32_t indexMask(BihIndexWidth width) { return (uint32_t{1} << indexBits(width)) - 1; }

}  // namespace

BihHeader bihSections(uint64_t nodes, uint64_t entries, uint64_t triangles, BihIndexWidth width) {
  if (nodes == 0) throw BihCapacityError("a tree needs a root node");
  const uint64_t indices = uint64_t{1} << indexBits(width);
  const std::string bits =
      std::to_string(indexBits(width)) + "-bit node indices" +
      (width == BihIndexWidth::Seed ? "; the wide index (accel.index = wide, --index wide) has 29"
                                    : "");
  checkCount(nodes, indices, "nodes", bits);
  checkCount(entries, indices, "list entries", bits);
  checkCount(triangles, uint64_t{1} << kBihTriangleNumberBits, "triangles",
             "triangle numbers have 29 bits");
  BihHeader header;
  std::string error;
  if (!placeSections(nodes, kBihNodeWords, entries, triangles, kBihTriangleWords, header, error))
    throw BihCapacityError(error);
  header.flags = width == BihIndexWidth::Wide ? kBihWideFlag : 0;
  return header;
}

std::vector<std::string> bihCapacityWarnings(const BihHeader& header) {
  std::vector<std::string> warnings;
  warnAbove(warnings, header.nodeCount, kBihSeedNodes, "nodes");
  warnAbove(warnings, header.listCount, kBihSeedEntries, "list entries");
  return warnings;
}

BihImage layOut(const BihBuild& build, const ProjectedMesh& projected, const SceneGrid& grid,
                BihIndexWidth width) {
  BihHeader header =
      bihSections(build.nodes.size(), build.list.size(), projected.triangles.size(), width);
  const GridPoint upper = sceneUpper(grid);
  header.upperX = static_cast<uint32_t>(upper[0]);
  header.upperY = static_cast<uint32_t>(upper[1]);
  header.upperZ = static_cast<uint32_t>(upper[2]);
  header.format = encodeFormat(grid.format());
  BihImage image{std::vector<uint32_t>(header.totalWords, 0), bihCapacityWarnings(header)};
  uint32_t* words = image.words.data();
  const auto headerWords = encodeHeader(header);
  std::copy(headerWords.begin(), headerWords.end(), words);
  for (size_t a = 0; a < build.nodes.size(); ++a) {
    const auto node = encodeNode(nodeOf(build.nodes[a]), width);
    std::copy(node.begin(), node.end(), words + header.nodeBase + kBihNodeWords * a);
  }
  std::copy(build.list.begin(), build.list.end(), words + header.listBase);
  for (size_t t = 0; t < projected.triangles.size(); ++t) {
    const auto record = toWords(projected.triangles[t]);
    std::copy(record.begin(), record.end(), words + header.triangleBase + kBihTriangleWords * t);
  }
  return image;
}

uint32_t encodeFormat(const FixedTriangleFormat& f) {
  uint32_t word = 0;
  const int fields[5] = {f.n, f.m, f.E, f.T, f.C};
  for (int i = 0; i < 5; ++i) word |= static_cast<uint32_t>(fields[i]) << (kFieldBits * i);
  return word | (f.listing == FixedListing::Vhdl ? kVhdlBit : 0);
}

FixedTriangleFormat decodeFormat(uint32_t word) {
  const auto field = [word](int i) {
    return static_cast<int>((word >> (kFieldBits * i)) & ((1u << kFieldBits) - 1));
  };
  return FixedTriangleFormat{
      field(0), field(1), field(2),
      field(3), field(4), (word & kVhdlBit) != 0 ? FixedListing::Vhdl : FixedListing::C99};
}

std::array<uint32_t, kBihHeaderWords> encodeHeader(const BihHeader& header) {
  std::array<uint32_t, kBihHeaderWords> words{};
  writeSections(header, words.data());
  for (size_t i = 0; i < kOwnFields.size(); ++i)
    words[kImageSectionWords + i] = header.*kOwnFields[i];
  return words;
}

BihHeader decodeBihHeader(const uint32_t* words) {
  BihHeader header;
  static_cast<ImageSections&>(header) = readSections(words);
  for (size_t i = 0; i < kOwnFields.size(); ++i)
    header.*kOwnFields[i] = words[kImageSectionWords + i];
  return header;
}

std::array<uint32_t, kBihNodeWords> encodeNode(const BihNode& node, BihIndexWidth width) {
  return {node.axis | (node.index & indexMask(width)) << 3, node.clip0, node.clip1, 0};
}

BihNode decodeNode(const uint32_t* words, BihIndexWidth width) {
  return {words[0] & 3u, (words[0] >> 3) & indexMask(width), words[1], words[2]};
}

}  // namespace rtu
