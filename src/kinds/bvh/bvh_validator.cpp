#include "kinds/bvh/bvh_validator.h"

#include <cmath>

#include "kinds/bvh/bvh_image.h"

namespace rtu {
namespace {

using Problems = ImageProblems;

std::string nodeName(uint32_t index) { return "node " + std::to_string(index); }
std::string triangleName(uint32_t index) { return "triangle " + std::to_string(index); }

bool inverted(const Aabb<float>& box) {
  for (int k = 0; k < 3; ++k)
    if (!(box.lower[k] <= box.upper[k])) return true;  // NaN included
  return false;
}

// The header against the format and against the placement its counts imply; false when the
// sections cannot be read.
bool checkHeader(const std::vector<uint32_t>& words, Problems& problems) {
  if (words.size() < kBvhHeaderWords) {
    problems.add(0, "the image has " + std::to_string(words.size()) +
                        " words, fewer than a header's " + std::to_string(kBvhHeaderWords));
    return false;
  }
  const BvhHeader header = decodeHeader(words.data());
  checkHeaderWord(problems, 0, "magic", header.magic, kBvhMagic);
  checkHeaderWord(problems, 1, "kind", header.kind, kBvhKind);
  checkHeaderWord(problems, 2, "version", header.version, kBvhVersion);
  checkHeaderWord(problems, 3, "flags", header.flags, 0);
  for (uint32_t word = 11; word < kBvhHeaderWords; ++word)
    checkHeaderWord(problems, word, "reserved word " + std::to_string(word), words[word], 0);
  BvhHeader placed;
  try {
    placed = bvhSections(header.nodeCount, header.listCount, header.triangleCount);
  } catch (const BvhCapacityError& error) {
    problems.add(5, error.what());
    return false;
  }
  checkPlacement(header, placed, words.size(), "reference", problems);
  return problems.empty();
}

// The checks past the header, over an image whose sections lie where its header says.
class Validator {
 public:
  Validator(const std::vector<uint32_t>& words, Problems& problems)
      : words_(words),
        view_(words),
        header_(view_.header()),
        problems_(problems),
        reached_(header_.nodeCount, false),
        leavesOfRef_(header_.listCount, 0),
        refsOfTriangle_(header_.triangleCount, 0) {}

  void run() {
    walkTree();
    checkUnreachedNodes();
    checkReferences();
    checkTriangles();
  }

 private:
  void walkTree() {
    std::vector<uint32_t> pending{0};
    reached_[0] = true;
    while (!pending.empty()) {
      const uint32_t index = pending.back();
      pending.pop_back();
      const BvhNode node = view_.node(index);
      if (inverted(node.box) && !(node.leaf && node.rightOrCount == 0))
        problem(view_.nodeAddress(index),
                nodeName(index) + ": its box is inverted or not a number");
      if (node.leaf)
        checkLeaf(index, node);
      else
        checkChildren(index, node, pending);
    }
  }

  void checkChildren(uint32_t index, const BvhNode& node, std::vector<uint32_t>& pending) {
    const uint32_t children[2] = {node.leftOrFirst, node.rightOrCount};
    for (int side = 0; side < 2; ++side) {
      const uint32_t child = children[side];
      const uint64_t word = view_.nodeAddress(index) + 6 + side;
      if (child >= header_.nodeCount) {
        problem(word, nodeName(index) + ": child " + std::to_string(child) + " is outside the " +
                          std::to_string(header_.nodeCount) + " nodes");
      } else if (reached_[child]) {
        problem(word, nodeName(index) + ": child " + std::to_string(child) +
                          " is reached a second time (a cycle or a shared node)");
      } else {
        reached_[child] = true;
        if (!node.box.contains(view_.node(child).box))
          problem(view_.nodeAddress(index), nodeName(index) + ": its box does not enclose child " +
                                                std::to_string(child) + "'s");
        pending.push_back(child);
      }
    }
  }

  void checkLeaf(uint32_t index, const BvhNode& node) {
    const uint64_t end = uint64_t{node.leftOrFirst} + node.rightOrCount;
    if (end > header_.listCount) {
      problem(view_.nodeAddress(index) + 7,
              nodeName(index) + ": its references " + std::to_string(node.leftOrFirst) + " to " +
                  std::to_string(end - 1) + " go beyond the " + std::to_string(header_.listCount) +
                  " of the array");
      return;
    }
    for (uint32_t i = node.leftOrFirst; i < end; ++i) {
      ++leavesOfRef_[i];
      const uint32_t triangle = view_.ref(i);
      if (triangle >= header_.triangleCount) continue;  // reported by checkReferences
      ++refsOfTriangle_[triangle];
      if (!encloses(node.box, view_.triangle(triangle)))
        problem(view_.nodeAddress(index),
                nodeName(index) + ": its box does not enclose " + triangleName(triangle));
    }
  }

  static bool encloses(const Aabb<float>& box, const BvhTriangle& triangle) {
    for (const glm::vec3& vertex : triangle.vertices)
      if (!box.contains(Aabb<float>{vertex, vertex})) return false;
    return true;
  }

  void checkUnreachedNodes() {
    for (uint32_t i = 0; i < header_.nodeCount; ++i)
      if (!reached_[i]) problem(view_.nodeAddress(i), nodeName(i) + " is reached from no parent");
  }

  void checkReferences() {
    for (uint32_t i = 0; i < header_.listCount; ++i) {
      const std::string name = "reference " + std::to_string(i);
      if (leavesOfRef_[i] != 1)
        problem(view_.refAddress(i),
                name + " is in " + std::to_string(leavesOfRef_[i]) + " leaves, not 1");
      if (view_.ref(i) >= header_.triangleCount)
        problem(view_.refAddress(i), name + ": triangle " + std::to_string(view_.ref(i)) +
                                         " is outside the " +
                                         std::to_string(header_.triangleCount) + " triangles");
    }
  }

  void checkTriangles() {
    for (uint32_t t = 0; t < header_.triangleCount; ++t) {
      const uint64_t word = view_.triangleAddress(t);
      if (refsOfTriangle_[t] != 1)
        problem(word, triangleName(t) + " is referenced by " + std::to_string(refsOfTriangle_[t]) +
                          " leaf entries, not 1");
      const uint32_t source = view_.triangle(t).source;
      if (source != t)
        problem(word + 9,
                triangleName(t) + ": its word 9 names triangle " + std::to_string(source));
      if (words_[word + 10] != 0 || words_[word + 11] != 0)
        problem(word + 10, triangleName(t) + ": words 10-11 are not 0");
    }
  }

  void problem(uint64_t word, const std::string& what) { problems_.add(word, what); }

  const std::vector<uint32_t>& words_;
  const BvhImageView view_;
  const BvhHeader header_;
  Problems& problems_;
  std::vector<bool> reached_;
  std::vector<uint32_t> leavesOfRef_;     // leaves whose range holds each reference
  std::vector<uint32_t> refsOfTriangle_;  // references naming each triangle, in leaves
};

}  // namespace

std::vector<BvhProblem> validateBvh(const std::vector<uint32_t>& words) {
  Problems problems("BVH");
  if (checkHeader(words, problems)) Validator(words, problems).run();
  return problems.take();
}

}  // namespace rtu
