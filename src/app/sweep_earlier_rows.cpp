#include "app/sweep_earlier_rows.h"

#include <fstream>

#include "base/input_file.h"

namespace rtu {
namespace {

using Json = nlohmann::ordered_json;

constexpr size_t kNone = static_cast<size_t>(-1);

bool finished(const Json& row) { return row["status"] == "ok" || row["status"] == "invalid"; }

}  // namespace

EarlierRows::EarlierRows(std::string jsonLinesPath) : path_(std::move(jsonLinesPath)) {
  forEachRow([this](size_t line, const Json& row) {
    Rows& rows =
        configurations_.try_emplace(digest(row["config"].dump()), Rows{line}).first->second;
    if (finished(row)) rows.lastFinished = line;
  });
}

// 128 bits (FNV-1a and a variant with another offset and a shift), so that two of 10^9
// configurations collide with a chance below 10^-20.
EarlierRows::Digest EarlierRows::digest(const std::string& text) {
  Digest value{14695981039346656037ull, 0x84222325cbf29ce4ull};
  for (const char c : text) {
    value.a = (value.a ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    value.b = (value.b ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    value.b ^= value.b >> 29;
  }
  return value;
}

bool EarlierRows::sweep(const std::string& configuration) {
  const auto found = configurations_.find(digest(configuration));
  if (found == configurations_.end()) return false;
  found->second.swept = true;
  return found->second.lastFinished != kNone;
}

size_t EarlierRows::keptLine(const Rows& rows) {
  if (rows.lastFinished != kNone) return rows.lastFinished;
  return rows.swept ? kNone : rows.first;
}

size_t EarlierRows::keptCount() const {
  size_t count = 0;
  for (const auto& [digest, rows] : configurations_) count += keptLine(rows) != kNone;
  return count;
}

void EarlierRows::forEachKept(const std::function<void(const Json&)>& keep) const {
  if (configurations_.empty()) return;
  forEachRow([&](size_t line, const Json& row) {
    if (keptLine(configurations_.at(digest(row["config"].dump()))) == line) keep(row);
  });
}

void EarlierRows::forEachRow(const std::function<void(size_t, const Json&)>& each) const {
  std::ifstream file = openInputFileIfAny(path_, "earlier sweep rows");
  std::string text;
  for (size_t line = 0; std::getline(file, text); ++line) {
    Json row;
    try {
      row = Json::parse(text);
    } catch (const nlohmann::json::exception&) {
      continue;
    }
    if (row.contains("config") && row.contains("status")) each(line, row);
  }
}

}  // namespace rtu
