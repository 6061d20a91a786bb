#include "base/nesting_depth.h"

#include <stdexcept>
#include <vector>

namespace rtu {

namespace {

[[noreturn]] void tooDeep(const std::string& text, size_t at) {
  size_t line = 1;
  for (size_t i = 0; i < at && i < text.size(); ++i) line += text[i] == '\n';
  throw std::invalid_argument("nested more than " + std::to_string(kMaxNesting) +
                              " levels deep at line " + std::to_string(line));
}

// The index of the last character of the string starting at `start` (a quote): JSON and TOML
// basic strings with backslash escapes, TOML literal strings and both triple-quoted forms.
size_t stringEnd(const std::string& text, size_t start) {
  const char quote = text[start];
  const bool escapes = quote == '"';
  const bool triple = text.compare(start, 3, std::string(3, quote)) == 0;
  const std::string closing(triple ? 3 : 1, quote);
  for (size_t i = start + closing.size(); i < text.size(); ++i) {
    if (escapes && text[i] == '\\') {
      ++i;
    } else if (text.compare(i, closing.size(), closing) == 0) {
      return i + closing.size() - 1;
    } else if (!triple && text[i] == '\n') {
      return i - 1;  // an unclosed one-line string; the parser will say so
    }
  }
  return text.size() - 1;
}

// TOML's nesting at one point: the table header's parts, then per open array or inline table the
// dotted key parts before it, plus the parts of the key being read.
class TomlDepth {
 public:
  explicit TomlDepth(const std::string& text) : text_(text) {}

  void check() {
    for (size_t i = 0; i < text_.size(); ++i) {
      const char c = text_[i];
      if (c == '"' || c == '\'') {
        i = stringEnd(text_, i);
      } else if (c == '#') {
        i = lineEnd(i) - 1;
      } else if (c == '\n') {
        lineStart_ = true;
        if (open_.empty()) keyParts_ = 0, inKey_ = true;
        continue;
      } else if (c == '[' && lineStart_ && open_.empty()) {
        i = header(i);
      } else if (c == '[' || c == '{') {
        open_.push_back({c, keyParts_});
        keyParts_ = 0;
        inKey_ = c == '{';
      } else if ((c == ']' || c == '}') && !open_.empty()) {
        keyParts_ = open_.back().keyParts;
        open_.pop_back();
        inKey_ = false;  // the array or table was a value
      } else if (c == ',' && !open_.empty() && open_.back().bracket == '{') {
        keyParts_ = 0;
        inKey_ = true;
      } else if (c == '=') {
        inKey_ = false;
      } else if (c == '.' && inKey_) {
        ++keyParts_;
      }
      if (c != ' ' && c != '\t' && c != '\r') lineStart_ = false;
      if (depth() > kMaxNesting) tooDeep(text_, i);
    }
  }

 private:
  struct Open {
    char bracket;
    int keyParts;  // of the key the array or table is the value of
  };

  size_t lineEnd(size_t i) const {
    const size_t end = text_.find('\n', i);
    return end == std::string::npos ? text_.size() : end;
  }

  // A [table] or [[array of tables]] header: its dotted parts; returns the index of its last
  // character (the rest of the line holds at most a comment).
  size_t header(size_t start) {
    headerParts_ = 1;
    const size_t end = lineEnd(start);
    for (size_t i = start; i < end; ++i) {
      if (text_[i] == '"' || text_[i] == '\'')
        i = stringEnd(text_, i);
      else if (text_[i] == '.')
        ++headerParts_;
      if (headerParts_ > kMaxNesting) tooDeep(text_, i);
    }
    keyParts_ = 0;
    return end - 1;
  }

  int depth() const {
    int total = headerParts_ + keyParts_ + static_cast<int>(open_.size());
    for (const Open& open : open_) total += open.keyParts;
    return total;
  }

  const std::string& text_;
  std::vector<Open> open_;
  int headerParts_ = 0, keyParts_ = 0;
  bool inKey_ = true, lineStart_ = true;
};

}  // namespace

void checkJsonNesting(const std::string& text) {
  int depth = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '"')
      i = stringEnd(text, i);
    else if (text[i] == '[' || text[i] == '{')
      ++depth;
    else if (text[i] == ']' || text[i] == '}')
      --depth;
    if (depth > kMaxNesting) tooDeep(text, i);
  }
}

void checkTomlNesting(const std::string& text) { TomlDepth(text).check(); }

}  // namespace rtu
