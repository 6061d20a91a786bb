#pragma once
// The rows an earlier sweep wrote into the same files, read a line at a time and held as a digest
// of each configuration with where its rows are (not the rows themselves): which of this sweep's
// points are done, and which earlier rows the rewritten files keep. Memory follows the rows
// written, not the grid.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>

#include <nlohmann/json.hpp>

namespace rtu {

class EarlierRows {
 public:
  // Reads `jsonLinesPath` if it exists; a line cut short by an interruption is dropped.
  explicit EarlierRows(std::string jsonLinesPath);
  bool empty() const { return configurations_.empty(); }
  // Marks the configuration (its JSON text) as one this sweep runs; whether it has a finished row
  // (ok or invalid, which would fail alike).
  bool sweep(const std::string& configuration);
  // Calls keep(row) for each row the sweep keeps, in the file's order: per configuration its last
  // finished row, else, for a configuration this sweep does not run (an earlier grid, preset or
  // list), its first failed row; each configuration once. A failed row of this sweep's (a scene
  // file since fixed, a stalled run) is dropped: it runs again.
  void forEachKept(const std::function<void(const nlohmann::ordered_json&)>& keep) const;
  size_t keptCount() const;

 private:
  struct Digest {
    uint64_t a, b;
    bool operator==(const Digest& other) const { return a == other.a && b == other.b; }
  };
  struct DigestHash {
    size_t operator()(const Digest& digest) const { return digest.a; }
  };
  struct Rows {
    size_t first;                                   // its first row's line
    size_t lastFinished = static_cast<size_t>(-1);  // none
    bool swept = false;
  };
  static Digest digest(const std::string& text);
  // The line kept of a configuration's rows, or -1.
  static size_t keptLine(const Rows& rows);
  // Calls row(line number, row) for each complete row of the file.
  void forEachRow(const std::function<void(size_t, const nlohmann::ordered_json&)>& row) const;

  std::string path_;
  std::unordered_map<Digest, Rows, DigestHash> configurations_;
};

}  // namespace rtu
