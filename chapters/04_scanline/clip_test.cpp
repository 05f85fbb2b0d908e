#include "chapters/04_scanline/clip.hpp"

#include <catch2/catch.hpp>

#include "tests/support/pixels.hpp"

using tri::testing::PixelSet;
using tri::testing::written_pixels;

TEST_CASE("The row range of a loop is cut to the canvas rows", "[04_scanline][clip][safety]") {
  const tri::Canvas canvas(10, 20);
  const auto inside = tri::ch04::rows_on_canvas(canvas, 3, 7);
  CHECK(inside.first == 3);
  CHECK(inside.last == 7);
  const auto huge =
      tri::ch04::rows_on_canvas(canvas, -(std::int64_t{1} << 31), std::int64_t{1} << 31);
  CHECK(huge.first == 0);
  CHECK(huge.last == 19);
  const auto below = tri::ch04::rows_on_canvas(canvas, -50, -1);
  CHECK(below.first > below.last);  // empty: the loop body never runs
}

TEST_CASE("A span is filled between its ends in either order, both ends included",
          "[04_scanline][clip][spans]") {
  tri::Canvas canvas(10, 4);
  canvas.enable_write_counts();
  tri::ch04::fill_span_between(canvas, 1, 6, 3, tri::colors::white);
  CHECK(written_pixels(canvas) == PixelSet{{3, 1}, {4, 1}, {5, 1}, {6, 1}});
  tri::ch04::fill_span_between(canvas, 2, 7, 7, tri::colors::white);
  CHECK(written_pixels(canvas).count({7, 2}) == 1);
  CHECK(written_pixels(canvas).size() == 5);
}

TEST_CASE("A span reaching far past the canvas is clipped before any pixel is written",
          "[04_scanline][clip][safety]") {
  tri::Canvas canvas(10, 4);
  canvas.enable_write_counts();
  const std::int64_t far = std::int64_t{1} << 31;
  tri::ch04::fill_span_between(canvas, 2, -far, far, tri::colors::white);
  tri::ch04::fill_span_between(canvas, -1, 0, 9, tri::colors::white);
  tri::ch04::fill_span_between(canvas, 4, 0, 9, tri::colors::white);
  tri::ch04::fill_span_between(canvas, 1, far, far + 5, tri::colors::white);
  tri::ch04::fill_span_between(canvas, 1, -far, -1, tri::colors::white);
  tri::ch04::put_pixel_if_on_canvas(canvas, -1, 0, tri::colors::white);
  tri::ch04::put_pixel_if_on_canvas(canvas, 10, 0, tri::colors::white);
  tri::ch04::put_pixel_if_on_canvas(canvas, 3, far, tri::colors::white);
  tri::ch04::put_pixel_if_on_canvas(canvas, 3, 3, tri::colors::white);
  CHECK(written_pixels(canvas).size() == 11);  // row 2 whole, and (3, 3)
  CHECK(canvas.outside_writes() == 0);
}
