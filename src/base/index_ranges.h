#pragma once
// A set of indices held as sorted disjoint ranges [begin, end): the rows of a sweep still to run,
// all of its points but the ones done, held by the rows done rather than by the grid. As text
// (a Slurm plan's rows): "0-9,12-99" (inclusive ends), "" for none.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace rtu {

class IndexRanges {
 public:
  IndexRanges() = default;
  // [begin, end).
  static IndexRanges span(size_t begin, size_t end) {
    IndexRanges all;
    if (begin < end) all.ranges_.emplace_back(begin, end);
    return all;
  }
  // Adds i, which must be greater than every index added before.
  void add(size_t i) {
    if (!ranges_.empty() && i < ranges_.back().second)
      throw std::logic_error("IndexRanges::add: indices must increase");
    if (!ranges_.empty() && ranges_.back().second == i)
      ++ranges_.back().second;
    else
      ranges_.emplace_back(i, i + 1);
  }
  size_t count() const {
    size_t total = 0;
    for (const auto& [begin, end] : ranges_) total += end - begin;
    return total;
  }
  bool empty() const { return ranges_.empty(); }
  size_t first() const { return ranges_.front().first; }
  size_t last() const { return ranges_.back().second - 1; }
  // Calls f(i) for each index in order.
  template <class F>
  void forEach(const F& f) const {
    for (const auto& [begin, end] : ranges_)
      for (size_t i = begin; i < end; ++i) f(i);
  }
  // The indices one at a time: next(i) sets i to the next one, false after the last.
  class Cursor {
   public:
    explicit Cursor(const IndexRanges& set) : set_(set) {}
    bool next(size_t& i) {
      while (range_ < set_.ranges_.size()) {
        const auto& [begin, end] = set_.ranges_[range_];
        if (offset_ < end - begin) {
          i = begin + offset_++;
          return true;
        }
        ++range_;
        offset_ = 0;
      }
      return false;
    }

   private:
    const IndexRanges& set_;
    size_t range_ = 0, offset_ = 0;
  };

  std::string text() const {
    std::string out;
    for (const auto& [begin, end] : ranges_)
      out += (out.empty() ? "" : ",") + std::to_string(begin) + "-" + std::to_string(end - 1);
    return out;
  }
  // Throws std::invalid_argument for text that is not increasing ranges.
  static IndexRanges parse(const std::string& text) {
    IndexRanges set;
    size_t start = 0;
    while (start < text.size()) {
      size_t comma = text.find(',', start);
      if (comma == std::string::npos) comma = text.size();
      const std::string range = text.substr(start, comma - start);
      const size_t dash = range.find('-');
      size_t used = 0, usedEnd = 0;
      if (dash == std::string::npos || dash == 0)
        throw std::invalid_argument("bad index range '" + range + "'");
      const size_t begin = std::stoull(range.substr(0, dash), &used);
      const size_t last = std::stoull(range.substr(dash + 1), &usedEnd);
      if (used != dash || usedEnd != range.size() - dash - 1 || last < begin ||
          (!set.empty() && begin <= set.last()))
        throw std::invalid_argument("bad index range '" + range + "'");
      set.ranges_.emplace_back(begin, last + 1);
      start = comma + 1;
    }
    return set;
  }

 private:
  std::vector<std::pair<size_t, size_t>> ranges_;
};

}  // namespace rtu
