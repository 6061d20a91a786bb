#include "kinds/bih/bih_validator.h"

#include <algorithm>
#include <stdexcept>

#include "kinds/bih/bih_image.h"

namespace rtu {
namespace {

bool checkFormat(const BihHeader& header, ImageProblems& problems) {
  const FixedTriangleFormat format = decodeFormat(header.format);
  try {
    validateFixedTriangleFormat(format);
  } catch (const std::invalid_argument& error) {
    problems.add(14, error.what());
    return false;
  }
  const uint32_t highest = static_cast<uint32_t>((uint64_t{1} << format.n) - 1);
  const uint32_t upper[3] = {header.upperX, header.upperY, header.upperZ};
  for (uint32_t k = 0; k < 3; ++k)
    if (upper[k] > highest)
      problems.add(11 + k, "the scene box's upper bound " + std::to_string(upper[k]) +
                               " is beyond the grid's " + std::to_string(highest));
  return true;
}

// The header against the format and the placement its counts imply; false when the sections
// cannot be read.
bool checkHeader(const std::vector<uint32_t>& words, ImageProblems& problems) {
  if (words.size() < kBihHeaderWords) {
    problems.add(0, "the image has " + std::to_string(words.size()) +
                        " words, fewer than a header's " + std::to_string(kBihHeaderWords));
    return false;
  }
  const BihHeader header = decodeBihHeader(words.data());
  checkHeaderWord(problems, 0, "magic", header.magic, kBihMagic);
  checkHeaderWord(problems, 1, "kind", header.kind, kBihKind);
  checkHeaderWord(problems, 2, "version", header.version, kBihVersion);
  checkHeaderWord(problems, 3, "flags", header.flags & ~kBihWideFlag, 0);
  checkHeaderWord(problems, 15, "reserved word 15", words[15], 0);
  if (!checkFormat(header, problems)) return false;
  BihHeader placed;
  try {
    placed = bihSections(header.nodeCount, header.listCount, header.triangleCount, header.width());
  } catch (const BihCapacityError& error) {
    problems.add(5, error.what());
    return false;
  }
  checkPlacement(header, placed, words.size(), "list", problems);
  return problems.empty();
}

std::string nodeName(uint32_t a) { return "node " + std::to_string(a); }
std::string triangleName(uint32_t t) { return "triangle " + std::to_string(t); }

// A node to visit: its interval box on the grid and its depth.
struct Visit {
  uint32_t node = 0;
  GridPoint lower{}, upper{};
  uint32_t depth = 0;
};

// The checks past the header, over an image whose sections lie where its header says.
class Validator {
 public:
  Validator(const std::vector<uint32_t>& words, ImageProblems& problems)
      : words_(words),
        header_(decodeBihHeader(words.data())),
        format_(decodeFormat(header_.format)),
        problems_(problems),
        reached_(header_.nodeCount, false),
        leavesOfEntry_(header_.listCount, 0),
        entriesOfTriangle_(header_.triangleCount, 0) {}

  void run() {
    walkTree();
    for (uint32_t a = 0; a < header_.nodeCount; ++a)
      if (!reached_[a]) problems_.add(nodeAddress(a), nodeName(a) + " is reached from no parent");
    checkList();
    checkTriangles();
  }

 private:
  uint64_t nodeAddress(uint32_t a) const { return header_.nodeBase + uint64_t{kBihNodeWords} * a; }
  uint64_t triangleAddress(uint32_t t) const {
    return header_.triangleBase + uint64_t{kBihTriangleWords} * t;
  }

  void walkTree() {
    std::vector<Visit> pending{Visit{0, {0, 0, 0}, header_.sceneUpper(), 0}};
    reached_[0] = true;
    while (!pending.empty()) {
      const Visit visit = pending.back();
      pending.pop_back();
      const uint64_t address = nodeAddress(visit.node);
      const BihNode node = decodeNode(&words_[address], header_.width());
      checkNodeWords(visit, address);
      if (node.leaf())
        checkLeaf(visit, node, address);
      else
        visitChildren(visit, node, address, pending);
    }
  }

  void checkNodeWords(const Visit& visit, uint64_t address) {
    const std::string name = nodeName(visit.node);
    const uint32_t used = (((uint64_t{1} << indexBits(header_.width())) - 1) << 3) | 3u;
    if ((words_[address] & ~used) != 0)
      problems_.add(address, name + ": bit 2 or a bit above its index is set");
    if (words_[address + 3] != 0) problems_.add(address + 3, name + ": its pad word is not 0");
    if (visit.depth > kBihMaxDepth)
      problems_.add(address, name + ": at depth " + std::to_string(visit.depth) + ", deeper than " +
                                 std::to_string(kBihMaxDepth) + " (the 32-entry stack)");
  }

  void visitChildren(const Visit& visit, const BihNode& node, uint64_t address,
                     std::vector<Visit>& pending) {
    if (uint64_t{node.index} + 1 >= header_.nodeCount) {
      problems_.add(address, nodeName(visit.node) + ": children " + std::to_string(node.index) +
                                 " and " + std::to_string(uint64_t{node.index} + 1) +
                                 " are not both among the " + std::to_string(header_.nodeCount) +
                                 " nodes");
      return;
    }
    for (uint32_t side = 0; side < 2; ++side) {
      const uint32_t child = node.index + side;
      if (reached_[child]) {
        problems_.add(address, nodeName(visit.node) + ": child " + std::to_string(child) +
                                   " is reached a second time (a cycle or a shared node)");
        continue;
      }
      reached_[child] = true;
      Visit next{child, visit.lower, visit.upper, visit.depth + 1};
      if (side == 0)
        next.upper[node.axis] = std::min<int64_t>(next.upper[node.axis], node.clip0);
      else
        next.lower[node.axis] = std::max<int64_t>(next.lower[node.axis], node.clip1);
      pending.push_back(next);
    }
  }

  void checkLeaf(const Visit& visit, const BihNode& node, uint64_t address) {
    const std::string name = nodeName(visit.node);
    if (node.clip1 != 0) problems_.add(address + 2, name + ": a leaf's clip1 word is not 0");
    if (node.count() == 0)
      problems_.add(address + 1, name + ": a leaf of 0 triangles (the FSM's counter would wrap)");
    const uint64_t end = uint64_t{node.index} + node.count();
    if (end > header_.listCount) {
      problems_.add(address + 1, name + ": its entries " + std::to_string(node.index) + " to " +
                                     std::to_string(end - 1) + " go beyond the list's " +
                                     std::to_string(header_.listCount));
      return;
    }
    for (uint32_t i = node.index; i < end; ++i) {
      ++leavesOfEntry_[i];
      const uint32_t t = words_[header_.listBase + i];
      if (t >= header_.triangleCount) continue;  // reported by checkList
      ++entriesOfTriangle_[t];
      checkFirstVertex(visit, t, address);
    }
  }

  // The record keeps its first vertex's p and q coordinates: they must lie in the leaf's box.
  void checkFirstVertex(const Visit& visit, uint32_t t, uint64_t leafAddress) {
    const uint64_t record = triangleAddress(t);
    const uint32_t r = words_[record + 2];
    if (r > 2) return;  // reported by checkTriangles
    const uint32_t axes[2] = {(r + 1) % 3, (r + 2) % 3};
    for (int i = 0; i < 2; ++i) {
      const int64_t c = words_[record + 3 + i];
      if (c < visit.lower[axes[i]] || c > visit.upper[axes[i]])
        problems_.add(leafAddress, nodeName(visit.node) + ": " + triangleName(t) +
                                       "'s first vertex lies outside the leaf's interval box");
    }
  }

  void checkList() {
    for (uint32_t i = 0; i < header_.listCount; ++i) {
      const uint64_t address = header_.listBase + uint64_t{i};
      const std::string name = "list entry " + std::to_string(i);
      if (leavesOfEntry_[i] != 1)
        problems_.add(address,
                      name + " is in " + std::to_string(leavesOfEntry_[i]) + " leaves, not 1");
      if (words_[address] >= header_.triangleCount)
        problems_.add(address, name + ": triangle " + std::to_string(words_[address]) +
                                   " is outside the " + std::to_string(header_.triangleCount) +
                                   " triangles");
    }
  }

  void checkTriangles() {
    const uint32_t gridEnd = static_cast<uint32_t>((uint64_t{1} << format_.n) - 1);
    for (uint32_t t = 0; t < header_.triangleCount; ++t) {
      const uint64_t record = triangleAddress(t);
      if (entriesOfTriangle_[t] == 0) problems_.add(record, triangleName(t) + " is in no leaf");
      if (words_[record + 2] > 2)
        problems_.add(record + 2, triangleName(t) + ": its axis r is " +
                                      std::to_string(words_[record + 2]) + ", not 0, 1 or 2");
      for (uint32_t i = 3; i < 5; ++i)
        if (words_[record + i] > gridEnd)
          problems_.add(record + i, triangleName(t) + ": a coordinate beyond the grid");
    }
  }

  const std::vector<uint32_t>& words_;
  const BihHeader header_;
  const FixedTriangleFormat format_;
  ImageProblems& problems_;
  std::vector<bool> reached_;
  std::vector<uint32_t> leavesOfEntry_;      // leaves whose range holds each list entry
  std::vector<uint32_t> entriesOfTriangle_;  // entries naming each triangle, in leaves
};

}  // namespace

std::vector<ImageProblem> validateBih(const std::vector<uint32_t>& words) {
  ImageProblems problems("BIH");
  if (checkHeader(words, problems)) Validator(words, problems).run();
  return problems.take();
}

}  // namespace rtu
