// IndexRanges: a sweep's rows to run as ranges, held by the gaps rather than the indices.

#include <catch2/catch.hpp>

#include <vector>

#include "base/index_ranges.h"

using namespace rtu;

TEST_CASE("Index ranges hold increasing indices as ranges and read back from their text",
          "[sweep]") {
  IndexRanges rows;
  for (size_t i : {1, 3, 5, 6, 7}) rows.add(i);
  CHECK(rows.count() == 5);
  CHECK(rows.first() == 1);
  CHECK(rows.last() == 7);
  CHECK(rows.text() == "1-1,3-3,5-7");
  std::vector<size_t> seen;
  IndexRanges::Cursor cursor(rows);
  for (size_t i; cursor.next(i);) seen.push_back(i);
  CHECK(seen == std::vector<size_t>{1, 3, 5, 6, 7});
  CHECK(IndexRanges::parse(rows.text()).text() == rows.text());
  CHECK_THROWS(rows.add(7));
  // 10^12 rows in one range: a count, not a list.
  const IndexRanges all = IndexRanges::span(0, 1000000000000u);
  CHECK(all.count() == 1000000000000u);
  CHECK(all.text() == "0-999999999999");
  CHECK(IndexRanges::parse("").empty());
  CHECK_THROWS_AS(IndexRanges::parse("5-3"), std::invalid_argument);
  CHECK_THROWS_AS(IndexRanges::parse("0-4,3-6"), std::invalid_argument);
  CHECK_THROWS_AS(IndexRanges::parse("0-x"), std::invalid_argument);
}
