#include "geometry/ply_header_check.h"

#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace rtu {
namespace {

constexpr size_t kMaxHeaderBytes = 64 * 1024;

// A problem with the header, before the file's path is added to the message.
struct HeaderProblem {
  std::string text;
};

struct PlyElement {
  std::string name;
  uint64_t count;
};

struct PlyHeader {
  std::vector<PlyElement> elements;
  size_t bytes = 0;  // up to and including the end_header line
};

// Header lines are ASCII; comments may hold UTF-8 (a tool's or an author's name).
bool isHeaderText(char c, bool comment) {
  const auto byte = static_cast<unsigned char>(c);
  return (byte >= ' ' && byte <= '~') || c == '\r' || c == '\t' || (comment && byte >= 0x80);
}

bool parseCount(const std::string& text, uint64_t& count) {
  if (text.empty() || text.size() > 19) return false;  // 19 digits always fit in 64 bits
  count = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return false;
    count = count * 10 + static_cast<uint64_t>(c - '0');
  }
  return true;
}

// Adds the element an `element NAME COUNT` line declares; other lines are left to assimp.
void readHeaderLine(const std::string& line, size_t lineNumber, PlyHeader& header) {
  std::istringstream words(line);
  std::string keyword, count;
  words >> keyword;
  const bool comment = keyword == "comment" || keyword == "obj_info";
  for (char c : line)
    if (!isHeaderText(c, comment))
      throw HeaderProblem{"line " + std::to_string(lineNumber) + " is not text"};
  PlyElement element;
  if (keyword != "element") return;
  words >> element.name >> count;
  if (!parseCount(count, element.count))
    throw HeaderProblem{"line " + std::to_string(lineNumber) + ": element '" + element.name +
                        "' has the count '" + count + "', not a non-negative integer"};
  header.elements.push_back(element);
}

bool isEndHeader(const std::string& line) {
  std::istringstream words(line);
  std::string keyword, rest;
  return words >> keyword && keyword == "end_header" && !(words >> rest);
}

// `start`: the file's first bytes, at most kMaxHeaderBytes.
PlyHeader parseHeader(const std::string& start) {
  PlyHeader header;
  for (size_t lineNumber = 1;; ++lineNumber) {
    const size_t lineEnd = start.find('\n', header.bytes);
    if (lineEnd == std::string::npos)
      throw HeaderProblem{start.size() == kMaxHeaderBytes
                              ? "has no end_header line in its first 64 KiB"
                              : "has no end_header line"};
    const std::string line = start.substr(header.bytes, lineEnd - header.bytes);
    header.bytes = lineEnd + 1;
    if (isEndHeader(line)) return header;
    readHeaderLine(line, lineNumber, header);
  }
}

void checkElementCounts(const PlyHeader& header, uint64_t fileBytes) {
  const uint64_t bodyBytes = fileBytes - header.bytes;
  for (const PlyElement& element : header.elements)
    if (element.count > bodyBytes)
      throw HeaderProblem{"declares " + std::to_string(element.count) + " '" + element.name +
                          "' elements but only " + std::to_string(bodyBytes) +
                          " bytes follow the header"};
}

}  // namespace

void checkPlyHeader(const std::string& path) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) return;  // assimp says why it cannot read it
  const auto fileBytes = static_cast<uint64_t>(file.tellg());
  file.seekg(0);
  std::string start(kMaxHeaderBytes, '\0');
  file.read(start.data(), static_cast<std::streamsize>(start.size()));
  start.resize(static_cast<size_t>(file.gcount()));
  if (start.compare(0, 3, "ply") != 0 && start.compare(0, 3, "PLY") != 0) return;  // as assimp
  try {
    checkElementCounts(parseHeader(start), fileBytes);
  } catch (const HeaderProblem& problem) {
    throw std::runtime_error("mesh '" + path + "': PLY header " + problem.text);
  }
}

}  // namespace rtu
