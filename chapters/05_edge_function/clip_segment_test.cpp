#include "clip_segment.hpp"

#include <catch2/catch.hpp>

namespace {

using tri::ch05::clip_segment_to_pixels;

}  // namespace

TEST_CASE("A segment is cut to the squares of the shown pixels", "[figures]") {
  // Pixels 0..9 cover [-0.5, 9.5] on both axes.
  SECTION("inside: unchanged") {
    const auto s = clip_segment_to_pixels({1, 2}, {8, 3}, {0, 0}, {9, 9});
    REQUIRE(s);
    CHECK((*s)[0] == glm::dvec2(1, 2));
    CHECK((*s)[1] == glm::dvec2(8, 3));
  }
  SECTION("crossing: both ends on the border, in the order a to b") {
    const auto s = clip_segment_to_pixels({-10.5, 4}, {19.5, 4}, {0, 0}, {9, 9});
    REQUIRE(s);
    CHECK((*s)[0] == glm::dvec2(-0.5, 4));
    CHECK((*s)[1] == glm::dvec2(9.5, 4));
  }
  SECTION("a diagonal from far away") {
    const auto s = clip_segment_to_pixels({-100.5, -100.5}, {99.5, 99.5}, {0, 0}, {9, 9});
    REQUIRE(s);
    // The ends come from a + t (b - a): equal up to rounding.
    CHECK((*s)[0].x == Approx(-0.5));
    CHECK((*s)[0].y == Approx(-0.5));
    CHECK((*s)[1].x == Approx(9.5));
    CHECK((*s)[1].y == Approx(9.5));
  }
  SECTION("missing: empty") {
    CHECK_FALSE(clip_segment_to_pixels({-5, -5}, {-1, 20}, {0, 0}, {9, 9}));
    CHECK_FALSE(clip_segment_to_pixels({0, 12}, {9, 12}, {0, 0}, {9, 9}));
  }
}
