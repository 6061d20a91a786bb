#pragma once
// A bound on the nesting of text inputs, checked before they are parsed (issue 33): a JSON
// configuration nested 20,000 deep overflowed the stack in the recursive walk over its values,
// and toml++ builds and frees dotted keys 100,000 deep by recursion inside the library, where no
// later check can help. Nothing rtusim reads nests more than a few levels.

#include <string>

namespace rtu {

constexpr int kMaxNesting = 64;

// Throw std::invalid_argument "nested more than 64 levels deep at line N" when the JSON or TOML
// `text` nests deeper than kMaxNesting: arrays and objects (inline tables), and in TOML also the
// parts of dotted keys and table headers. Strings and comments are skipped; the text need not be
// valid (the parser says what else is wrong).
void checkJsonNesting(const std::string& text);
void checkTomlNesting(const std::string& text);

}  // namespace rtu
