#include "geometry/obj_exact.h"

#include <cerrno>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "base/input_file.h"

namespace rtu {
namespace {

class LineError {
 public:
  LineError(const std::string& name, int line) : where_(name + ":" + std::to_string(line)) {}
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(where_ + ": " + what);
  }

 private:
  std::string where_;
};

double number(const std::string& token, const LineError& error) {
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(token.c_str(), &end);
  if (token.empty() || *end != '\0' || errno == ERANGE) error.fail("not a number: '" + token + "'");
  return value;
}

glm::dvec3 point(std::istringstream& in, const LineError& error) {
  glm::dvec3 p;
  for (int k = 0; k < 3; ++k) {
    std::string token;
    if (!(in >> token)) error.fail("expected three coordinates");
    p[k] = number(token, error);
  }
  return p;
}

// A 1-based index field within [1, count], as 0-based.
int32_t index(const std::string& field, size_t count, const LineError& error) {
  char* end = nullptr;
  const long value = std::strtol(field.c_str(), &end, 10);
  if (field.empty() || *end != '\0' || value < 1 || size_t(value) > count)
    error.fail("index '" + field + "' is not in 1.." + std::to_string(count));
  return static_cast<int32_t>(value - 1);
}

struct Corner {
  int32_t position = -1, normal = -1;
};

Corner corner(const std::string& token, const ObjMesh& obj, const LineError& error) {
  const size_t first = token.find('/');
  Corner c;
  c.position = index(token.substr(0, first), obj.mesh.vertices.size(), error);
  if (first == std::string::npos) return c;
  const size_t second = token.find('/', first + 1);
  if (second != std::string::npos)
    c.normal = index(token.substr(second + 1), obj.normals.size(), error);
  return c;
}

void face(std::istringstream& in, ObjMesh& obj, const LineError& error) {
  std::vector<Corner> corners;
  std::string token;
  while (in >> token) corners.push_back(corner(token, obj, error));
  if (corners.size() < 3 || corners.size() > 4)
    error.fail("a face has 3 or 4 corners, not " + std::to_string(corners.size()));
  const auto add = [&obj](const Corner& a, const Corner& b, const Corner& c) {
    obj.mesh.triangles.push_back(
        {uint32_t(a.position), uint32_t(b.position), uint32_t(c.position)});
    obj.cornerNormals.push_back({a.normal, b.normal, c.normal});
  };
  add(corners[0], corners[1], corners[2]);
  if (corners.size() == 4) add(corners[2], corners[3], corners[0]);
}

}  // namespace

ObjMesh parseObjExact(const std::string& text, const std::string& name) {
  ObjMesh obj;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream in(line);
    std::string keyword;
    in >> keyword;
    const LineError error(name, number);
    if (keyword == "v")
      obj.mesh.vertices.push_back(point(in, error));
    else if (keyword == "vn")
      obj.normals.push_back(point(in, error));
    else if (keyword == "f")
      face(in, obj, error);
  }
  if (obj.mesh.triangles.empty()) throw std::runtime_error(name + ": no faces");
  return obj;
}

ObjMesh readObjExact(const std::string& path) {
  // Read whole like the mesh loader's answer; bounded as a word image is.
  return parseObjExact(readInputFile(path, "OBJ file", uint64_t{16} << 30), path);
}

}  // namespace rtu
