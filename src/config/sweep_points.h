#pragma once
// A sweep's configurations as an indexed lazy sequence: point i is computed from i alone
// (mixed-radix decoding: the list entry, then the grid's keys in order, the last key fastest), so
// that what a sweep holds does not grow with its grid. Its checks, resume, dry run and Slurm plan
// (array tasks take indices) all take points by index.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "config/configuration.h"
#include "config/sweep_spec.h"

namespace rtu {

class SweepPoints {
 public:
  // Checks each value of each key once, throwing std::invalid_argument naming the key for one the
  // schema rejects. Every point is a distinct configuration: values a key reads alike ("4" and
  // "4.0"), a key gridded again (the later grid's values win, as they would be set last) and list
  // entries that differ only in gridded keys count once. Throws for more points than an index
  // holds.
  SweepPoints(const SweepSpec& spec, const Configuration& base);

  size_t size() const { return entries_.size() * gridSize_; }
  // Point i (< size()): the base with the list entry's values and the grid's, each marked
  // ConfigSource::Sweep.
  Configuration at(size_t i) const;
  // The values point i sets, "scheduler=rr cores=4" (the base's for a sweep of one point: "").
  std::string describe(size_t i) const;

  // The sequence as JSON (the base's values, the grid's keys and values, the list), and back: a
  // Slurm array task computes the same points from their indices (the base's sources are File).
  nlohmann::ordered_json toJson() const;
  static SweepPoints fromJson(const nlohmann::ordered_json& json);

 private:
  SweepPoints() = default;
  SweepSpec::Assignments assignments(size_t i) const;

  Configuration base_;
  std::vector<SweepSpec::Assignments> entries_;
  std::vector<std::pair<std::string, std::vector<std::string>>> axes_;  // key, distinct values
  size_t gridSize_ = 1;
};

}  // namespace rtu
