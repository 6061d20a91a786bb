#include "geometry/ply_header_check.h"

#include <algorithm>
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

// A property's bytes in a binary body: a value's, or a list's count and each of its values'.
struct PlyProperty {
  bool list = false;
  uint32_t countBytes = 0;  // a list's count (0: not a list)
  uint32_t valueBytes = 0;  // 0: a type PLY does not name
};

struct PlyElement {
  std::string name;
  uint64_t count;
  // Its properties in order: true for a list (a count, then that many values).
  std::vector<bool> lists;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  std::vector<PlyElement> elements;
  bool ascii = false;
  bool bigEndian = false;
  size_t bytes = 0;  // up to and including the end_header line
};

// Header lines are ASCII; comments may hold UTF-8 (a tool's or an author's name).
bool isHeaderText(char c, bool comment) {
  const auto byte = static_cast<unsigned char>(c);
  return (byte >= ' ' && byte <= '~') || c == '\r' || c == '\t' || (comment && byte >= 0x80);
}

// The bytes of a PLY scalar type in a binary body; 0 for a name PLY does not have.
uint32_t typeBytes(const std::string& type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" ||
      type == "float32")
    return 4;
  if (type == "double" || type == "float64") return 8;
  return 0;
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
    header.bigEndian = format == "binary_big_endian";
  }
  if (keyword == "property" && !header.elements.empty()) {
    std::string type, valueType;
    words >> type;
    PlyProperty property;
    property.list = type == "list";
    if (property.list) {
      words >> type >> valueType;
      property.countBytes = typeBytes(type);
      property.valueBytes = typeBytes(valueType);
    } else {
      property.valueBytes = typeBytes(type);
    }
    header.elements.back().lists.push_back(property.list);
    header.elements.back().properties.push_back(property);
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

// The body of a binary file read forward in blocks: a list's count read, the rest skipped.
class BinaryBody {
 public:
  BinaryBody(std::istream& in, bool bigEndian) : in_(in), bigEndian_(bigEndian) {}

  // Skipped lazily: one seek for a run of values beyond the buffer.
  void skip(uint64_t bytes) { pending_ += bytes; }
  // A count of `bytes` bytes (1, 2 or 4) in the file's byte order; the caller knows it is there.
  uint64_t count(uint32_t bytes) {
    settle();
    uint64_t value = 0;
    for (uint32_t i = 0; i < bytes; ++i) {
      const uint64_t byte = next();
      value |= byte << (8 * (bigEndian_ ? bytes - 1 - i : i));
    }
    return value;
  }

 private:
  void settle() {
    const uint64_t buffered = std::min<uint64_t>(pending_, end_ - next_);
    next_ += buffered;
    pending_ -= buffered;
    if (pending_ == 0) return;
    in_.seekg(static_cast<std::streamoff>(pending_), std::ios::cur);
    pending_ = 0;
    next_ = end_ = 0;
  }
  uint64_t next() {
    if (next_ == end_) {
      in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
      next_ = 0;
      end_ = static_cast<uint64_t>(in_.gcount());
      in_.clear();
    }
    return static_cast<unsigned char>(buffer_[next_++]);
  }

  std::istream& in_;
  bool bigEndian_;
  std::vector<char> buffer_ = std::vector<char>(64 * 1024);
  uint64_t next_ = 0, end_ = 0;
  uint64_t pending_ = 0;
};

bool hasList(const PlyElement& element) {
  return std::find(element.lists.begin(), element.lists.end(), true) != element.lists.end();
}

// A binary body holds exactly the elements declared: their fixed-size properties, and each list's
// count then that many values. A header declaring more or fewer elements than held was read as
// another model (issue 33), as in an ASCII body. A body with a property of a type PLY does not
// name is left to assimp.
void checkBinaryBody(std::istream& in, const PlyHeader& header, uint64_t bodyBytes) {
  for (const PlyElement& element : header.elements)
    for (const PlyProperty& property : element.properties)
      if (property.valueBytes == 0 || (property.list && property.countBytes == 0)) return;
  BinaryBody body(in, header.bigEndian);
  uint64_t left = bodyBytes;  // bytes of the body not yet accounted for
  for (const PlyElement& element : header.elements) {
    if (!hasList(element)) {  // a fixed size: counted at once
      uint64_t each = 0;
      for (const PlyProperty& property : element.properties) each += property.valueBytes;
      if (each > 0 && element.count > left / each)
        throw HeaderProblem{
            "declares more data than the file holds: " + std::to_string(element.count) + " '" +
            element.name + "' elements of " + std::to_string(each) + " bytes, " +
            std::to_string(left) + " bytes left for them"};
      left -= element.count * each;
      body.skip(element.count * each);
      continue;
    }
    for (uint64_t i = 0; i < element.count; ++i) {
      const auto missing = [&] {
        return HeaderProblem{"declares more data than the file holds: '" + element.name +
                             "' element " + std::to_string(i + 1) + " of the " +
                             std::to_string(element.count) + " declared is cut off"};
      };
      for (const PlyProperty& property : element.properties) {
        uint64_t values = 1;
        if (property.list) {
          if (left < property.countBytes) throw missing();
          values = body.count(property.countBytes);
          left -= property.countBytes;
        }
        if (values > left / property.valueBytes) throw missing();
        left -= values * property.valueBytes;
        body.skip(values * property.valueBytes);
      }
    }
  }
  if (left > 0)
    throw HeaderProblem{"declares less data than the file holds: " + std::to_string(left) +
                        " bytes follow the last element"};
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
    } else {
      file.clear();
      file.seekg(static_cast<std::streamoff>(header.bytes));
      checkBinaryBody(file, header, fileBytes - header.bytes);
    }
  } catch (const HeaderProblem& problem) {
    throw std::runtime_error("mesh '" + path + "': PLY header " + problem.text);
  }
}

}  // namespace rtu
