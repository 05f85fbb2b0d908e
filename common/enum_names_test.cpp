#include <catch2/catch.hpp>

#include <string_view>

#include "common/enum_names.hpp"

namespace {

enum class Shade { light, mid, dark };

constexpr auto shade_names = tri::all_names<Shade::dark>(
    {{Shade::light, "light"}, {Shade::mid, "mid"}, {Shade::dark, "dark"}});

}  // namespace

TEST_CASE("An enumeration's names table names each value and reads each name back",
          "[common][enum_names]") {
  for (const Shade shade : {Shade::light, Shade::mid, Shade::dark}) {
    const std::string_view name = tri::name_in(shade_names, shade, "?");
    CAPTURE(name);
    CHECK(name != "?");
    CHECK(tri::value_named(shade_names, name) == shade);
  }
  CHECK(tri::name_in(shade_names, Shade::mid, "?") == "mid");
}

TEST_CASE(
    "An enumeration's names table gives the fallback for a value it lacks and nothing for "
    "another word",
    "[common][enum_names]") {
  CHECK(tri::name_in(shade_names, static_cast<Shade>(7), "?") == "?");
  CHECK_FALSE(tri::value_named(shade_names, "Mid").has_value());
  CHECK_FALSE(tri::value_named(shade_names, "").has_value());
}
