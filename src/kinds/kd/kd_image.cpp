#include "kinds/kd/kd_image.h"

#include <stdexcept>
#include <string>

#include "base/float_bits.h"

namespace rtu {
namespace {

constexpr std::array<uint32_t KdHeader::*, 10> kHeaderFields = {
    &KdHeader::magic,      &KdHeader::version,   &KdHeader::nodeBase, &KdHeader::nodeCount,
    &KdHeader::listBase,   &KdHeader::listCount, &KdHeader::uttmBase, &KdHeader::uttmCount,
    &KdHeader::totalWords, &KdHeader::flags};
constexpr int kBoxWord = 10;

constexpr uint32_t kChildLimit = uint32_t{1} << 28;  // word 1 bits 29:2
constexpr uint32_t kCountLimit = uint32_t{1} << 30;  // word 1 bits 29:0

uint64_t alignedToAccess(uint64_t words) { return (words + 3) / 4 * 4; }

void checkFits(uint64_t value, uint64_t limit, const std::string& what) {
  if (value >= limit)
    throw std::length_error("k-d image: " + what + " " + std::to_string(value) +
                            " does not fit (limit " + std::to_string(limit) + ")");
}

// The header layOutKd writes for these counts.
KdHeader sectionsFor(uint64_t nodes, uint64_t lists, uint64_t uttms) {
  KdHeader header;
  const uint64_t listBase = alignedToAccess(kKdHeaderWords + kKdNodeWords * nodes);
  const uint64_t uttmBase = alignedToAccess(listBase + lists);
  const uint64_t total = uttmBase + kKdUttmWords * uttms;
  checkFits(total, uint64_t{1} << 32, "image size in words");
  header.nodeBase = kKdHeaderWords;
  header.nodeCount = uint32_t(nodes);
  header.listBase = uint32_t(listBase);
  header.listCount = uint32_t(lists);
  header.uttmBase = uint32_t(uttmBase);
  header.uttmCount = uint32_t(uttms);
  header.totalWords = uint32_t(total);
  return header;
}

}  // namespace

std::array<uint32_t, kKdHeaderWords> encodeKdHeader(const KdHeader& header) {
  std::array<uint32_t, kKdHeaderWords> words{};
  for (size_t i = 0; i < kHeaderFields.size(); ++i) words[i] = header.*kHeaderFields[i];
  for (int k = 0; k < 6; ++k) words[kBoxWord + k] = floatBits(header.box[k]);
  return words;
}

KdHeader decodeKdHeader(const uint32_t* words) {
  KdHeader header;
  for (size_t i = 0; i < kHeaderFields.size(); ++i) header.*kHeaderFields[i] = words[i];
  for (int k = 0; k < 6; ++k) header.box[k] = bitsToFloat(words[kBoxWord + k]);
  return header;
}

std::array<uint32_t, kKdNodeWords> encodeKdNode(const TrayRacerNode& node) {
  if (node.leaf) {
    checkFits(node.count, kCountLimit, "leaf triangle count");
    return {node.listIndex, kKdLeafAxis << 30 | node.count};
  }
  checkFits(node.high, kChildLimit, "child node id");
  return {node.splitBits,
          node.axis << 30 | node.high << 2 | uint32_t(node.lowEmpty) << 1 | node.highEmpty};
}

TrayRacerNode decodeKdNode(const uint32_t* words) {
  TrayRacerNode node;
  const uint32_t axis = words[1] >> 30;
  node.leaf = axis == kKdLeafAxis;
  if (node.leaf) {
    node.listIndex = words[0];
    node.count = words[1] & (kCountLimit - 1);
  } else {
    node.axis = axis;
    node.splitBits = words[0];
    node.high = words[1] >> 2 & (kChildLimit - 1);
    node.lowEmpty = words[1] >> 1 & 1;
    node.highEmpty = words[1] & 1;
  }
  return node;
}

KdImage layOutKd(const TrayRacerScene& scene) {
  KdHeader header = sectionsFor(scene.nodes.size(), scene.lists.size(), scene.uttms.size());
  header.box = scene.box;
  KdImage image;
  image.words.assign(header.totalWords, 0);
  const auto h = encodeKdHeader(header);
  std::copy(h.begin(), h.end(), image.words.begin());
  for (size_t i = 0; i < scene.nodes.size(); ++i) {
    const auto n = encodeKdNode(scene.nodes[i]);
    std::copy(n.begin(), n.end(), image.words.begin() + header.nodeBase + kKdNodeWords * i);
  }
  std::copy(scene.lists.begin(), scene.lists.end(), image.words.begin() + header.listBase);
  for (size_t i = 0; i < scene.uttms.size(); ++i)
    std::copy(scene.uttms[i].begin(), scene.uttms[i].end(),
              image.words.begin() + header.uttmBase + kKdUttmWords * i);
  return image;
}

namespace {

bool headerSound(const std::vector<uint32_t>& words, const KdHeader& header,
                 ImageProblems& problems) {
  if (header.magic != kKdMagic || header.version != kKdVersion) {
    problems.add(0, "not a k-d image of version " + std::to_string(kKdVersion));
    return false;
  }
  KdHeader expected = sectionsFor(header.nodeCount, header.listCount, header.uttmCount);
  expected.box = header.box;
  expected.flags = header.flags;
  if (encodeKdHeader(expected) != encodeKdHeader(header)) {
    problems.add(2, "sections are not where the counts place them");
    return false;
  }
  if (header.totalWords != words.size()) {
    problems.add(8, "the header says " + std::to_string(header.totalWords) +
                        " words, the image has " + std::to_string(words.size()));
    return false;
  }
  return true;
}

void checkNode(const KdHeader& header, uint32_t index, const TrayRacerNode& node,
               ImageProblems& problems) {
  const uint64_t word = header.nodeBase + uint64_t{kKdNodeWords} * index;
  const std::string name = "node " + std::to_string(index) + ": ";
  if (node.leaf) {
    if (uint64_t{node.listIndex} + node.count > header.listCount)
      problems.add(word, name + "list beyond the lists");
  } else if ((!node.highEmpty && node.high >= header.nodeCount) ||
             (!node.lowEmpty && index + 1 >= header.nodeCount)) {
    problems.add(word + 1, name + "child outside the nodes");
  } else if (node.lowEmpty && node.highEmpty) {
    // R1's builder leaves such nodes (pbrt_kd_builder.h, pruneEmptyPairs); TRAV would take a ray
    // into the empty far child, a leaf whose list count the RTL's list path wraps.
    problems.add(word, name + "both children empty (a ray would enter an empty leaf); rebuild "
                              "with rtusim build, which prunes such nodes");
  }
}

}  // namespace

std::vector<ImageProblem> validateKd(const std::vector<uint32_t>& words) {
  ImageProblems problems("k-d");
  if (words.size() < kKdHeaderWords) {
    problems.add(0, "shorter than a header");
    return problems.take();
  }
  const KdHeader header = decodeKdHeader(words.data());
  if (!headerSound(words, header, problems)) return problems.take();
  for (int k = 0; k < 3; ++k)
    if (!(header.box[k] <= header.box[k + 3]))
      problems.add(kBoxWord + k, "scene box inverted on axis " + std::to_string(k));
  for (uint32_t i = 0; i < header.nodeCount; ++i)
    checkNode(header, i, decodeKdNode(&words[header.nodeBase + kKdNodeWords * i]), problems);
  for (uint32_t i = 0; i < header.listCount; ++i)
    if (words[header.listBase + i] >= header.uttmCount)
      problems.add(header.listBase + i, "list entry " + std::to_string(i) + " names no triangle");
  for (uint32_t i = 0; i < header.uttmCount; ++i)
    for (uint32_t w = kUttmWords; w < kKdUttmWords; ++w)
      if (words[header.uttmBase + kKdUttmWords * i + w] != 0)
        problems.add(header.uttmBase + kKdUttmWords * i + w,
                     "UTTM " + std::to_string(i) + ": padding word not zero");
  return problems.take();
}

}  // namespace rtu
