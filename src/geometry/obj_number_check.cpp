#include "geometry/obj_number_check.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rtu {

namespace {

bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Advances `i` over digits; whether there was one.
bool digits(const std::string& text, size_t& i) {
  const size_t start = i;
  while (i < text.size() && isDigit(text[i])) ++i;
  return i > start;
}

bool isDecimalNumber(const std::string& text) {
  size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  bool mantissa = digits(text, i);
  if (i < text.size() && text[i] == '.') mantissa = digits(text, ++i) || mantissa;
  if (!mantissa) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (!digits(text, i)) return false;
  }
  return i == text.size();
}

bool isObj(const std::string& path) {
  if (path.size() < 4) return false;
  std::string extension = path.substr(path.size() - 4);
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".obj";
}

}  // namespace

void checkObjNumbers(const std::string& path) {
  if (!isObj(path)) return;
  std::ifstream file(path, std::ios::binary);
  std::string line, keyword, value;
  for (size_t number = 1; std::getline(file, line); ++number) {
    std::istringstream words(line);
    if (!(words >> keyword) ||
        (keyword != "v" && keyword != "vn" && keyword != "vt" && keyword != "vp"))
      continue;
    while (words >> value)
      if (!isDecimalNumber(value))
        throw std::runtime_error("mesh '" + path + "', line " + std::to_string(number) + ": '" +
                                 value + "' is not a decimal number");
  }
}

}  // namespace rtu
