#include "kinds/svo/binvox.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "base/input_file.h"
#include "base/output_file.h"

namespace rtu {
namespace {

constexpr int kMaxRun = 255;

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw std::runtime_error("binvox file '" + path + "': " + problem);
}

// Cells of a level in binvox's nesting (x, then z, then y fastest), so a run along y is
// contiguous.
uint64_t cellIndex(int level, uint64_t x, uint64_t y, uint64_t z) {
  return ((x << level | z) << level) | y;
}

struct Header {
  int dim = 0;
  glm::dvec3 translate{0.0};
  double scale = 1.0;
};

// Reads exactly `values.size()` numbers and nothing more from the rest of a header line.
template <typename T>
bool readExactly(std::istringstream& words, std::vector<T>& values) {
  for (T& value : values)
    if (!(words >> value)) return false;
  std::string extra;
  return !(words >> extra);
}

class HeaderReader {
 public:
  HeaderReader(std::istream& in, const std::string& path) : in_(in), path_(path) {}

  Header read() {
    if (!nextLine()) fail(path_, "is empty");
    readMagic();
    Header header;
    while (nextLine()) {
      std::istringstream words(line_);
      std::string keyword;
      words >> keyword;
      if (keyword == "data") {
        if (header.dim == 0) fail(path_, "no 'dim' line before 'data'");
        return header;
      }
      if (keyword == "dim") {
        header.dim = readDim(words);
      } else if (keyword == "translate") {
        const std::vector<double> t = readNumbers<double>(words, 3, "three numbers");
        header.translate = glm::dvec3(t[0], t[1], t[2]);
      } else if (keyword == "scale") {
        header.scale = readNumbers<double>(words, 1, "one number")[0];
      }
      // Other keywords are skipped, as binvox's own reader does.
    }
    fail(path_, "header has no 'data' line");
  }

 private:
  bool nextLine() {
    if (!std::getline(in_, line_)) return false;
    ++lineNumber_;
    if (!line_.empty() && line_.back() == '\r') line_.pop_back();
    return true;
  }

  [[noreturn]] void failOnLine(const std::string& problem) const {
    fail(path_, "line " + std::to_string(lineNumber_) + ": " + problem);
  }

  void readMagic() {
    std::istringstream words(line_);
    std::string magic;
    int version = 0;
    if (!(words >> magic) || magic != "#binvox")
      failOnLine("bad magic: expected '#binvox 1', found '" + line_.substr(0, 40) + "'");
    if (!(words >> version) || version != 1)
      failOnLine("unsupported binvox version in '" + line_ + "' (only version 1)");
  }

  template <typename T>
  std::vector<T> readNumbers(std::istringstream& words, size_t count, const std::string& what) {
    std::vector<T> values(count);
    if (!readExactly(words, values)) failOnLine("'" + line_ + "' must hold " + what);
    return values;
  }

  int readDim(std::istringstream& words) {
    const std::vector<long long> dims = readNumbers<long long>(words, 3, "three whole numbers");
    if (dims[0] != dims[1] || dims[0] != dims[2])
      failOnLine("dimensions " + std::to_string(dims[0]) + " " + std::to_string(dims[1]) + " " +
                 std::to_string(dims[2]) + " are not cubic");
    if (dims[0] < 1 || dims[0] > kMaxBinvoxDim)
      failOnLine("dimension " + std::to_string(dims[0]) + " is outside 1 to " +
                 std::to_string(kMaxBinvoxDim));
    return static_cast<int>(dims[0]);
  }

  std::istream& in_;
  const std::string& path_;
  std::string line_;
  int lineNumber_ = 0;
};

// Checks that the (value, count) pairs cover exactly `voxels` voxels with values 0 and 1.
// `dataOffset` is the file offset of data[0], for the messages.
void checkRuns(const std::vector<uint8_t>& data, uint64_t voxels, uint64_t dataOffset,
               const std::string& path) {
  uint64_t covered = 0;
  for (size_t i = 0; i + 1 < data.size(); i += 2) {
    const std::string where = "run at byte " + std::to_string(dataOffset + i);
    if (data[i] > 1)
      fail(path, where + " has value " + std::to_string(data[i]) + " (must be 0 or 1)");
    covered += data[i + 1];
    if (covered > voxels)
      fail(path, where + " overflows the grid: runs cover more than its " + std::to_string(voxels) +
                     " voxels");
  }
  if (data.size() % 2 != 0)
    fail(path, "data is truncated: it ends inside the run at byte " +
                   std::to_string(dataOffset + data.size() - 1));
  if (covered < voxels)
    fail(path, "data is truncated: runs cover only " + std::to_string(covered) + " of " +
                   std::to_string(voxels) + " voxels");
}

int depthFor(int dim) {
  int depth = 1;
  while ((1 << depth) < dim) ++depth;
  return depth;
}

}  // namespace

BinvoxGrid::BinvoxGrid(const std::string& path) {
  uint64_t fileBytes = 0;
  std::ifstream in = openInputFile(path, "binvox file", fileBytes);
  const Header header = HeaderReader(in, path).read();
  const uint64_t dataOffset = static_cast<uint64_t>(in.tellg());
  const auto dim = static_cast<uint64_t>(header.dim);
  // A run covers at least one voxel, so more than two bytes a voxel is no grid (checked before
  // reading: zero-length runs would otherwise let any file size through).
  if (fileBytes - dataOffset > 2 * dim * dim * dim)
    fail(path, std::to_string(fileBytes - dataOffset) + " bytes of runs, more than 2 for each of " +
                   std::to_string(dim * dim * dim) + " voxels");
  const std::vector<uint8_t> data{std::istreambuf_iterator<char>(in),
                                  std::istreambuf_iterator<char>()};
  checkRuns(data, dim * dim * dim, dataOffset, path);

  dim_ = header.dim;
  depth_ = depthFor(dim_);
  translate_ = header.translate;
  scale_ = header.scale;
  anySolid_.resize(static_cast<size_t>(depth_) + 1);
  std::vector<bool>& grid = anySolid_[depth_];
  grid.resize(uint64_t{1} << 3 * depth_);

  uint64_t position = 0;  // binvox index: x * D * D + z * D + y
  for (size_t i = 0; i < data.size(); i += 2) {
    for (uint64_t left = data[i + 1]; left > 0;) {
      const uint64_t y = position % dim;
      const uint64_t run = std::min(left, dim - y);  // the part that stays in this y row
      if (data[i] == 1) {
        const uint64_t row = cellIndex(depth_, position / (dim * dim), 0, position / dim % dim);
        std::fill(grid.begin() + static_cast<std::ptrdiff_t>(row + y),
                  grid.begin() + static_cast<std::ptrdiff_t>(row + y + run), true);
        solidVoxels_ += run;
      }
      position += run;
      left -= run;
    }
  }
  buildSummaries();
}

bool BinvoxGrid::allSolid(int level, uint64_t index) const {
  return level == depth_ ? anySolid_[level][index] : allSolid_[level][index];
}

void BinvoxGrid::buildSummaries() {
  allSolid_.resize(static_cast<size_t>(depth_));
  for (int level = depth_ - 1; level >= 0; --level) {
    const uint64_t cells = uint64_t{1} << level;
    anySolid_[level].resize(cells * cells * cells);
    allSolid_[level].resize(cells * cells * cells);
    for (uint32_t x = 0; x < cells; ++x) {
      for (uint32_t y = 0; y < cells; ++y) {
        for (uint32_t z = 0; z < cells; ++z) {
          const OctreeNode node{level, x, y, z};
          bool any = false;
          bool all = true;
          for (int slot = 0; slot < 8; ++slot) {
            const OctreeNode child = node.child(slot);
            const uint64_t index = cellIndex(child.level, child.x, child.y, child.z);
            any = any || anySolid_[child.level][index];
            all = all && allSolid(child.level, index);
          }
          const uint64_t index = cellIndex(level, x, y, z);
          anySolid_[level][index] = any;
          allSolid_[level][index] = all;
        }
      }
    }
  }
}

Occupancy BinvoxGrid::classify(const OctreeNode& node) const {
  if (node.level < 0 || node.level > depth_)
    throw std::invalid_argument("node level " + std::to_string(node.level) +
                                " is outside the binvox grid's levels 0 to " +
                                std::to_string(depth_));
  const uint32_t cells = 1u << node.level;
  if (node.x >= cells || node.y >= cells || node.z >= cells)
    throw std::invalid_argument("node (" + std::to_string(node.x) + ", " + std::to_string(node.y) +
                                ", " + std::to_string(node.z) + ") is outside the " +
                                std::to_string(cells) + "^3 cells of level " +
                                std::to_string(node.level));
  const uint64_t index = cellIndex(node.level, node.x, node.y, node.z);
  if (!anySolid_[node.level][index]) return Occupancy::Empty;
  return allSolid(node.level, index) ? Occupancy::Full : Occupancy::Mixed;
}

void writeBinvox(const std::string& path, int dim,
                 const std::function<bool(int, int, int)>& solid) {
  if (dim < 1 || dim > kMaxBinvoxDim)
    throw std::invalid_argument("binvox dim must be 1 to " + std::to_string(kMaxBinvoxDim) +
                                ", got " + std::to_string(dim));
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << "#binvox 1\ndim " << dim << ' ' << dim << ' ' << dim
      << "\ntranslate 0 0 0\nscale 1\ndata\n";

  bool value = solid(0, 0, 0);
  int count = 0;
  auto endRun = [&] { out.put(static_cast<char>(value)).put(static_cast<char>(count)); };
  for (int x = 0; x < dim; ++x) {
    for (int z = 0; z < dim; ++z) {
      for (int y = 0; y < dim; ++y) {
        const bool voxel = solid(x, y, z);
        if (voxel != value || count == kMaxRun) {
          endRun();
          value = voxel;
          count = 0;
        }
        ++count;
      }
    }
  }
  endRun();
  file.commit();
}

}  // namespace rtu
