#pragma once
// What a structural validator of a memory image (a BVH's, a BIH's) reports: each problem names the
// word found wrong, so a corrupt image or file points at its fault. The list is capped, since a
// badly corrupt image can have a problem per word; a last entry then says so.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rtu {

struct ImageProblem {
  uint32_t word = 0;  // the address of the word found wrong (a record's first for a whole record)
  std::string what;   // "<format> word 23: node 0: ...", naming the node, entry or record
};

constexpr size_t kMaxImageProblems = 100;

// The problems found so far, at most kMaxImageProblems and then one entry saying so.
class ImageProblems {
 public:
  explicit ImageProblems(std::string format) : format_(std::move(format)) {}

  void add(uint64_t word, const std::string& what) {
    if (list_.size() > kMaxImageProblems) return;
    if (list_.size() == kMaxImageProblems) {
      list_.push_back({0, format_ + ": more than " + std::to_string(kMaxImageProblems) +
                              " problems; the rest are not listed"});
      return;
    }
    list_.push_back(
        {static_cast<uint32_t>(word), format_ + " word " + std::to_string(word) + ": " + what});
  }
  bool empty() const { return list_.empty(); }
  std::vector<ImageProblem> take() { return std::move(list_); }

 private:
  std::string format_;
  std::vector<ImageProblem> list_;
};

// The problems as one message: "<what> is not a sound <format> image:" then at most `shown`
// problems, one per line.
inline std::string describeImageProblems(const std::string& what, const std::string& format,
                                         const std::vector<ImageProblem>& problems, size_t shown) {
  std::string message = what + " is not a sound " + format + " image:";
  for (size_t i = 0; i < problems.size() && i < shown; ++i) message += "\n  " + problems[i].what;
  if (problems.size() > shown) message += "\n  ...";
  return message;
}

}  // namespace rtu
