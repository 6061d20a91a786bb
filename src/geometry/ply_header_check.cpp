#include "geometry/ply_header_check.h"

#include <cstdint>
#include <fstream>
#include <iterator>
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
  // Its properties in order: true for a list (a count, then that many values).
  std::vector<bool> lists;
};

struct PlyHeader {
  std::vector<PlyElement> elements;
  bool ascii = false;
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
  if (keyword == "format") {
    std::string format;
    words >> format;
    header.ascii = format == "ascii";
  }
  if (keyword == "property" && !header.elements.empty()) {
    std::string type;
    words >> type;
    header.elements.back().lists.push_back(type == "list");
  }
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

// The values one line of `element` must hold, given the line's words (a list's count among them),
// or 0 when a list's count is not a number.
uint64_t valuesOnLine(const PlyElement& element, const std::vector<std::string>& words) {
  uint64_t expected = 0;
  for (const bool list : element.lists) {
    if (!list) {
      ++expected;
      continue;
    }
    uint64_t length = 0;
    if (expected >= words.size() || !parseCount(words[expected], length)) return 0;
    expected += 1 + length;
  }
  return expected;
}

// An ASCII body holds each element on a line of its own. A header declaring more vertices than
// the body holds made assimp read faces as vertices, silently another model (issue 33): every
// element's lines are counted and their values checked against its properties.
void checkAsciiBody(std::istream& body, const PlyHeader& header) {
  std::string line;
  uint64_t lineNumber = 0;
  const auto nextLine = [&](std::vector<std::string>& words) {
    while (std::getline(body, line)) {
      ++lineNumber;
      std::istringstream in(line);
      words.assign(std::istream_iterator<std::string>(in), std::istream_iterator<std::string>());
      if (!words.empty()) return true;
    }
    return false;
  };
  std::vector<std::string> words;
  for (const PlyElement& element : header.elements) {
    for (uint64_t i = 0; i < element.count; ++i) {
      const std::string which = "'" + element.name + "' element " + std::to_string(i + 1) +
                                " of the " + std::to_string(element.count) + " declared";
      if (!nextLine(words))
        throw HeaderProblem{"declares more data than the file holds: " + which + " is missing"};
      if (valuesOnLine(element, words) != words.size())
        throw HeaderProblem{"does not match the data: " + which + " (body line " +
                            std::to_string(lineNumber) + ") has " + std::to_string(words.size()) +
                            " values"};
    }
  }
  if (nextLine(words))
    throw HeaderProblem{"declares less data than the file holds: body line " +
                        std::to_string(lineNumber) + " follows the last element"};
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
    const PlyHeader header = parseHeader(start);
    checkElementCounts(header, fileBytes);
    if (header.ascii) {
      file.clear();
      file.seekg(static_cast<std::streamoff>(header.bytes));
      checkAsciiBody(file, header);
    }
  } catch (const HeaderProblem& problem) {
    throw std::runtime_error("mesh '" + path + "': PLY header " + problem.text);
  }
}

}  // namespace rtu
