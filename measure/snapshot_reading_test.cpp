// The one snapshot reader: header lines by name, then numbers and texts by key in the file's order.
#include <catch2/catch.hpp>
#include <string>

#include "measure/snapshot_reading.hpp"

namespace {

const std::string kSnapshot =
    "# Measurement snapshot of chapter 10's report, quick setting\n"
    "# machine: Test CPU, 4 hardware threads\n"
    "# date: 2030-01-02\n"
    "# peers: pixman 0.42.2, cairo 1.16.0\n"
    "key,value\n"
    "fast.chapter,08_fast_exact\n"
    "fast.threaded,0\n"
    "fast.tiny_tris_per_s,3e+06\n"
    "area_cells.cost_vs_fastest,2.96831\n";

}  // namespace

TEST_CASE("A snapshot's header names its run and its KEY,VALUE lines hold numbers and texts",
          "[measure]") {
  const tri::Snapshot snapshot = tri::parse_snapshot(kSnapshot);
  CHECK(snapshot.header.size() == 3);  // the title line names nothing
  CHECK(snapshot.header_text("machine") == "Test CPU, 4 hardware threads");
  CHECK(snapshot.header_text("peers") == "pixman 0.42.2, cairo 1.16.0");
  CHECK(snapshot.header_text("note") == "unknown");
  CHECK(snapshot.numbers.size() == 3);
  CHECK(snapshot.number("fast.tiny_tris_per_s") == 3e6);
  CHECK(snapshot.number("area_cells.cost_vs_fastest") == 2.96831);
  CHECK_FALSE(snapshot.number("fast.chapter"));  // a text, not a number
  CHECK(snapshot.texts.size() == 1);
  CHECK(snapshot.texts.at("fast.chapter") == "08_fast_exact");
  REQUIRE(snapshot.keys.size() == 4);
  CHECK(snapshot.keys.front() == "fast.chapter");
  CHECK(snapshot.keys.back() == "area_cells.cost_vs_fastest");
}

TEST_CASE("A text that is not a snapshot is refused with the line that is not one", "[measure]") {
  CHECK_THROWS_WITH(tri::parse_snapshot("area_cells.cost_vs_fastest,2.9\n"),
                    Catch::Contains("line 1"));  // no key,value line
  CHECK_THROWS_WITH(tri::parse_snapshot("key,value\narea_cells\n"), Catch::Contains("line 2"));
  CHECK_THROWS_WITH(tri::parse_snapshot("key,value\narea_cells,\n"), Catch::Contains("no value"));
  CHECK_THROWS_WITH(tri::parse_snapshot("key,value\n,1\n"), Catch::Contains("no key"));
  CHECK_THROWS_WITH(tri::parse_snapshot("# machine: none\n"), Catch::Contains("no line key,value"));
}
