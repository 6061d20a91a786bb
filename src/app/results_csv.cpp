#include "app/results_csv.h"

#include <charconv>
#include <ostream>
#include <stdexcept>

#include "base/output_file.h"

namespace rtu {
namespace {

// The shortest text that reads back as `value`.
std::string shortest(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

std::string row(const ResultRow& r) {
  std::string line = std::to_string(r.id) + (r.hit ? ",1," : ",0,");
  if (r.hit) line += shortest(r.t);
  line += ',';
  if (r.hit && r.primitive) line += std::to_string(*r.primitive);
  line += ',';
  if (r.hit && r.u) line += shortest(*r.u);
  line += ',';
  if (r.hit && r.v) line += shortest(*r.v);
  for (uint64_t value : r.extra) line += ',' + std::to_string(value);
  return line;
}

}  // namespace

void writeResultsCsv(const std::string& path, const std::vector<ResultRow>& rows,
                     const std::vector<std::string>& extraColumns) {
  OutputFile file(path);
  file.stream() << "id,hit,t,primitive,u,v";
  for (const std::string& column : extraColumns) file.stream() << ',' << column;
  file.stream() << '\n';
  for (const ResultRow& r : rows) {
    if (r.extra.size() != extraColumns.size())
      throw std::logic_error("a result row's extra values do not match its columns");
    file.stream() << row(r) << '\n';
  }
  file.commit();
}

}  // namespace rtu
