#include <catch2/catch.hpp>

#include <string>

#include "base/nesting_depth.h"

using namespace rtu;

namespace {

std::string repeat(const std::string& part, int times) {
  std::string text;
  for (int i = 0; i < times; ++i) text += part;
  return text;
}

std::string dottedKey(int parts) { return "a" + repeat(".a", parts - 1); }

}  // namespace

TEST_CASE("JSON nested deeper than the bound is refused with its line", "[nesting]") {
  CHECK_NOTHROW(checkJsonNesting(repeat("[", kMaxNesting) + repeat("]", kMaxNesting)));
  CHECK_THROWS_WITH(checkJsonNesting("{\n\"a\":\n" + repeat("[", 20000) + repeat("]", 20000)),
                    "nested more than 64 levels deep at line 3");
  CHECK_THROWS_WITH(checkJsonNesting(repeat("{\"a\":", 100)), Catch::Contains("at line 1"));
  // Brackets in strings, escaped quotes included, are text.
  CHECK_NOTHROW(checkJsonNesting("{\"k\\\"[\": \"" + repeat("[{", 100) + "\"}"));
}

TEST_CASE("TOML nesting counts dotted keys\\, headers\\, arrays and inline tables", "[nesting]") {
  CHECK_NOTHROW(checkTomlNesting(dottedKey(kMaxNesting) + " = 1\n"));
  CHECK_THROWS_WITH(checkTomlNesting("x = 1\n" + dottedKey(100000) + " = 1\n"),
                    "nested more than 64 levels deep at line 2");
  CHECK_THROWS_WITH(checkTomlNesting("[" + dottedKey(100000) + "]\nb = 1\n"),
                    "nested more than 64 levels deep at line 1");
  CHECK_THROWS(checkTomlNesting("[" + dottedKey(40) + "]\n" + dottedKey(40) + " = 1\n"));
  CHECK_THROWS(checkTomlNesting("x = " + repeat("{a = ", 70) + "1" + repeat("}", 70)));
  CHECK_THROWS(checkTomlNesting("x = " + repeat("[", 70) + repeat("]", 70)));
  // Dots in values, strings and comments nest nothing.
  CHECK_NOTHROW(checkTomlNesting("x = [" + repeat("1.5, ", 200) + "2.5]\n"));
  CHECK_NOTHROW(checkTomlNesting("x = [{a = 1}, {}, " + repeat("0.5, ", 100) + "]\n"));
  CHECK_NOTHROW(checkTomlNesting("x = \"" + repeat("a.", 100) + "\" # " + repeat("[.", 100)));
  CHECK_NOTHROW(checkTomlNesting("x = '''\n" + repeat("[{.", 100) + "\n'''\ny = 1.0\n"));
  CHECK_NOTHROW(checkTomlNesting("[a.\"" + repeat(".", 100) + "\"]\nb.c = 1.5\n"));
}
