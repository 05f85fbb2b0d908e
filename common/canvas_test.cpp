#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/canvas.hpp"
#include "common/centered_view.hpp"
#include "tests/support/pixels.hpp"

namespace tri {
namespace {

using testing::PixelSet;
using testing::written_pixels;

// Catch prints std::array and std::pair, not glm vectors, so those are compared instead.
std::array<int, 4> rgba(Color c) {
  return {c.r, c.g, c.b, c.a};
}
std::pair<int, int> xy(glm::ivec2 p) {
  return {p.x, p.y};
}

// Checks where the centred view of canvas puts each view point: pairs of (view point, pixel).
void check_view_maps(const Canvas& canvas,
                     const std::vector<std::pair<glm::ivec2, std::pair<int, int>>>& expected) {
  const CenteredView view(canvas);
  for (const auto& [point, pixel] : expected) {
    CAPTURE(point.x, point.y);
    CHECK(xy(view.to_canvas(point)) == pixel);
  }
}

bool every_pixel_is(const Canvas& canvas, Color color) {
  for (const Color c : canvas.pixels()) {
    if (c != color) return false;
  }
  return true;
}

std::uint64_t sum_of_counts(const Canvas& canvas) {
  const auto counts = canvas.write_counts();
  return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
}

// 2^32 - 1: how many pixels the span INT_MIN <= x < INT_MAX holds.
constexpr std::uint64_t widest_span = 4294967295ULL;

}  // namespace

TEST_CASE("A canvas accepts every side from 1 to 16384", "[common][canvas]") {
  const Canvas smallest(1, 1);
  CHECK(smallest.width() == 1);
  CHECK(smallest.height() == 1);
  CHECK(smallest.pixels().size() == 1);

  // The largest side on one axis only: 64 KiB instead of the 1 GiB of a 16384x16384 canvas.
  const Canvas widest(max_canvas_side, 1);
  CHECK(widest.width() == 16384);
  CHECK(widest.pixels().size() == 16384);
  const Canvas tallest(1, max_canvas_side);
  CHECK(tallest.height() == 16384);
  CHECK(tallest.pixels().size() == 16384);
}

TEST_CASE("A canvas with a side of 0, a negative side or a side above 16384 is refused",
          "[common][canvas]") {
  const auto [width, height] = GENERATE(table<int, int>({{0, 1},
                                                         {1, 0},
                                                         {0, 0},
                                                         {-1, 10},
                                                         {10, -1},
                                                         {16385, 1},
                                                         {1, 16385},
                                                         {16385, 16385},
                                                         {INT_MIN, 1},
                                                         {1, INT_MIN},
                                                         {INT_MAX, 1},
                                                         {1, INT_MAX},
                                                         {INT_MAX, INT_MAX}}));
  INFO(width << "x" << height);
  CHECK_THROWS_AS(Canvas(width, height), std::invalid_argument);
  CHECK_THROWS_WITH(Canvas(width, height),
                    Catch::Contains(std::to_string(width) + "x" + std::to_string(height)) &&
                        Catch::Contains("1..16384"));
}

TEST_CASE("A new canvas holds its background colour and counts nothing", "[common][canvas]") {
  const Canvas canvas(4, 3, colors::blue);
  CHECK(canvas.pixels().size() == 12);
  CHECK(every_pixel_is(canvas, colors::blue));
  CHECK(rgba(Canvas(2, 2).pixel(1, 1)) == rgba(colors::black));
  CHECK_FALSE(canvas.write_counts_enabled());
  CHECK(canvas.write_counts().empty());
  CHECK(canvas.write_count(3, 2) == 0);
  CHECK(canvas.outside_writes() == 0);
}

TEST_CASE("Pixel (0, 0) is the first stored pixel and rows are stored bottom row first",
          "[common][canvas]") {
  Canvas canvas(3, 2);
  canvas.put_pixel(0, 0, colors::red);
  canvas.put_pixel(1, 0, colors::green);
  canvas.put_pixel(glm::ivec2(2, 1), colors::blue);

  const auto pixels = canvas.pixels();
  CHECK(rgba(pixels[0]) == rgba(colors::red));
  CHECK(rgba(pixels[1]) == rgba(colors::green));
  CHECK(rgba(pixels[5]) == rgba(colors::blue));
  CHECK(rgba(pixels[3]) == rgba(colors::black));  // (0, 1): the first pixel of the upper row

  CHECK(canvas.row(0).size() == 3);
  CHECK(canvas.row(0).data() == pixels.data());
  CHECK(canvas.row(1).data() == pixels.data() + 3);
  CHECK(rgba(canvas.row(1)[2]) == rgba(colors::blue));

  // Writing through row() is writing the pixel.
  canvas.row(1)[0] = colors::yellow;
  CHECK(rgba(canvas.pixel(0, 1)) == rgba(colors::yellow));
}

TEST_CASE("contains accepts exactly the pixels of the canvas", "[common][canvas]") {
  const Canvas canvas(4, 3);
  int inside = 0;
  for (int y = -2; y < 5; ++y) {
    for (int x = -2; x < 6; ++x) {
      const bool expected = x >= 0 && x < 4 && y >= 0 && y < 3;
      CHECK(canvas.contains(x, y) == expected);
      CHECK(canvas.contains(glm::ivec2(x, y)) == expected);
      if (canvas.contains(x, y)) ++inside;
    }
  }
  CHECK(inside == 12);
  CHECK_FALSE(canvas.contains(INT_MIN, 0));
  CHECK_FALSE(canvas.contains(INT_MAX, 0));
  CHECK_FALSE(canvas.contains(0, INT_MIN));
  CHECK_FALSE(canvas.contains(0, INT_MAX));
}

TEST_CASE("Writes outside the canvas are ignored and counted", "[common][canvas]") {
  Canvas canvas(4, 3, colors::gray);
  canvas.enable_write_counts();
  const std::vector<glm::ivec2> outside = {{-1, 0},
                                           {4, 0},
                                           {0, -1},
                                           {0, 3},
                                           {-1, -1},
                                           {4, 3},
                                           {INT_MIN, 0},
                                           {INT_MAX, 0},
                                           {0, INT_MIN},
                                           {0, INT_MAX},
                                           {INT_MIN, INT_MIN},
                                           {INT_MAX, INT_MAX}};
  for (const glm::ivec2 p : outside) canvas.put_pixel(p, colors::red);

  CHECK(canvas.outside_writes() == outside.size());
  CHECK(every_pixel_is(canvas, colors::gray));
  CHECK(sum_of_counts(canvas) == 0);

  // The last pixel of each row and column is still inside.
  canvas.put_pixel(3, 2, colors::red);
  CHECK(canvas.outside_writes() == outside.size());
  CHECK(written_pixels(canvas) == PixelSet{{3, 2}});
}

TEST_CASE("Write counts are off until enabled, then count every accepted write",
          "[common][canvas]") {
  Canvas canvas(3, 3);
  canvas.put_pixel(1, 1, colors::red);
  CHECK(canvas.write_count(1, 1) == 0);
  CHECK(canvas.write_counts().empty());

  canvas.enable_write_counts();
  CHECK(canvas.write_counts_enabled());
  CHECK(canvas.write_counts().size() == 9);
  CHECK(sum_of_counts(canvas) == 0);  // earlier writes are not counted

  for (int i = 0; i < 3; ++i) canvas.put_pixel(1, 1, colors::red);
  canvas.put_pixel(0, 2, colors::red);
  canvas.put_pixel(5, 5, colors::red);
  CHECK(canvas.write_count(1, 1) == 3);
  CHECK(canvas.write_count(0, 2) == 1);
  CHECK(canvas.write_counts()[2 * 3 + 0] == 1);  // counts are stored like pixels: bottom row first
  CHECK(sum_of_counts(canvas) == 4);
  CHECK(written_pixels(canvas) == PixelSet{{1, 1}, {0, 2}});
  CHECK(testing::overdrawn_pixels(canvas) == PixelSet{{1, 1}});
  CHECK(canvas.outside_writes() == 1);

  // Enabling again starts over from zero.
  canvas.enable_write_counts();
  CHECK(sum_of_counts(canvas) == 0);
}

TEST_CASE("clear paints every pixel and resets the write and outside counters",
          "[common][canvas]") {
  Canvas canvas(3, 2);
  canvas.enable_write_counts();
  canvas.put_pixel(0, 0, colors::red);
  canvas.put_pixel(2, 1, colors::red);
  canvas.put_pixel(-1, 0, colors::red);
  REQUIRE(canvas.outside_writes() == 1);

  canvas.clear(colors::cyan);
  CHECK(every_pixel_is(canvas, colors::cyan));
  CHECK(canvas.write_counts_enabled());
  CHECK(sum_of_counts(canvas) == 0);
  CHECK(canvas.outside_writes() == 0);
}

TEST_CASE("fill_span writes x_begin <= x < x_end, clipped to the canvas, and counts the rest",
          "[common][canvas][fill_span]") {
  struct Case {
    const char* what;
    int y, x_begin, x_end;
    PixelSet written;
    std::uint64_t outside;
  };
  // A 5x3 canvas: x in 0..4, y in 0..2.
  const std::vector<Case> cases = {
      {"inside", 1, 1, 4, {{1, 1}, {2, 1}, {3, 1}}, 0},
      {"one pixel", 0, 4, 5, {{4, 0}}, 0},
      {"whole row", 2, 0, 5, {{0, 2}, {1, 2}, {2, 2}, {3, 2}, {4, 2}}, 0},
      {"partly left", 0, -2, 2, {{0, 0}, {1, 0}}, 2},
      {"partly right", 0, 3, 8, {{3, 0}, {4, 0}}, 3},
      {"over both sides", 1, -3, 7, {{0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}}, 5},
      {"fully left", 1, -5, -1, {}, 4},
      {"ends where the canvas starts", 1, -5, 0, {}, 5},
      {"fully right", 1, 5, 9, {}, 4},
      {"row below", -1, 0, 5, {}, 5},
      {"row above", 3, 1, 3, {}, 2},
      {"empty", 1, 2, 2, {}, 0},
      {"reversed", 1, 4, 1, {}, 0},
      {"reversed and outside", 7, 9, -9, {}, 0},
      {"int range on a row",
       0,
       INT_MIN,
       INT_MAX,
       {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}},
       widest_span - 5},
      {"int range on row INT_MAX", INT_MAX, INT_MIN, INT_MAX, {}, widest_span},
      {"int range on row INT_MIN", INT_MIN, INT_MIN, INT_MAX, {}, widest_span},
      {"from INT_MIN into the canvas", 2, INT_MIN, 1, {{0, 2}}, 2147483648ULL},
      {"from the canvas to INT_MAX", 2, 4, INT_MAX, {{4, 2}}, 2147483642ULL},
      {"far right", 0, INT_MAX - 1, INT_MAX, {}, 1},
      {"far left", 0, INT_MIN, INT_MIN + 1, {}, 1},
  };
  for (const Case& c : cases) {
    INFO(c.what << ": y=" << c.y << " x=" << c.x_begin << ".." << c.x_end);
    Canvas canvas(5, 3);
    canvas.enable_write_counts();
    canvas.fill_span(c.y, c.x_begin, c.x_end, colors::red);
    CHECK(written_pixels(canvas) == c.written);
    CHECK(sum_of_counts(canvas) == c.written.size());  // each written pixel exactly once
    CHECK(canvas.outside_writes() == c.outside);
    for (const auto& [x, y] : c.written) CHECK(rgba(canvas.pixel(x, y)) == rgba(colors::red));
    int red = 0;
    for (const Color p : canvas.pixels()) red += p == colors::red ? 1 : 0;
    CHECK(red == static_cast<int>(c.written.size()));
  }
}

TEST_CASE("fill_span leaves colours alone and counts nothing per pixel when counting is off",
          "[common][canvas][fill_span]") {
  Canvas canvas(5, 3);
  canvas.fill_span(1, -1, 3, colors::green);
  CHECK(canvas.write_counts().empty());
  CHECK(canvas.outside_writes() == 1);
  CHECK(rgba(canvas.pixel(0, 1)) == rgba(colors::green));
  CHECK(rgba(canvas.pixel(2, 1)) == rgba(colors::green));
  CHECK(rgba(canvas.pixel(3, 1)) == rgba(colors::black));
  CHECK(rgba(canvas.pixel(0, 0)) == rgba(colors::black));
}

TEST_CASE("Overlapping spans add up their write counts", "[common][canvas][fill_span]") {
  Canvas canvas(6, 1);
  canvas.enable_write_counts();
  canvas.fill_span(0, 0, 4, colors::red);
  canvas.fill_span(0, 2, 6, colors::blue);
  const std::vector<std::uint32_t> expected = {1, 1, 2, 2, 1, 1};
  CHECK(std::vector<std::uint32_t>(canvas.write_counts().begin(), canvas.write_counts().end()) ==
        expected);
  CHECK(rgba(canvas.pixel(1, 0)) == rgba(colors::red));
  CHECK(rgba(canvas.pixel(2, 0)) == rgba(colors::blue));
}

TEST_CASE("fill_span does exactly what put_pixel does for every x of the span, on random spans",
          "[common][canvas][fill_span]") {
  testing::Random random(20240601);
  for (int trial = 0; trial < 500; ++trial) {
    const int y = random.integer(-2, 5);
    const int x_begin = random.integer(-10, 15);
    const int x_end = random.integer(-10, 15);
    INFO("y=" << y << " x=" << x_begin << ".." << x_end);
    Canvas by_span(7, 4);
    Canvas by_pixel(7, 4);
    by_span.enable_write_counts();
    by_pixel.enable_write_counts();
    by_span.fill_span(y, x_begin, x_end, colors::magenta);
    for (int x = x_begin; x < x_end; ++x) by_pixel.put_pixel(x, y, colors::magenta);
    CHECK(std::equal(by_span.pixels().begin(), by_span.pixels().end(), by_pixel.pixels().begin()));
    CHECK(std::equal(by_span.write_counts().begin(), by_span.write_counts().end(),
                     by_pixel.write_counts().begin()));
    CHECK(by_span.outside_writes() == by_pixel.outside_writes());
  }
}

TEST_CASE("The centred view maps (0, 0) to the middle of the canvas, y up",
          "[common][canvas][view]") {
  Canvas canvas(600, 600);
  check_view_maps(canvas, {{{0, 0}, {300, 300}},
                           // The vertices of Gambetta's figure 7-1.
                           {{-200, -250}, {100, 50}},
                           {{200, 50}, {500, 350}},
                           {{20, 250}, {320, 550}},
                           {{-300, -300}, {0, 0}},
                           {{299, 299}, {599, 599}}});
  // Up in the view is up on the canvas: no flip.
  CHECK(CenteredView(canvas).to_canvas({0, 1}).y == 301);
}

TEST_CASE("The centred view of an odd-sized canvas rounds the middle down",
          "[common][canvas][view]") {
  Canvas canvas(5, 3);
  check_view_maps(canvas, {{{0, 0}, {2, 1}}, {{-2, -1}, {0, 0}}, {{2, 1}, {4, 2}}});
}

TEST_CASE("The centred view maps points past the canvas's edges to pixels off the canvas",
          "[common][canvas][view]") {
  const Canvas canvas(6, 4);
  const CenteredView view(canvas);
  CHECK(canvas.contains(view.to_canvas({0, 0})));
  CHECK(canvas.contains(view.to_canvas({-3, -2})));
  CHECK(canvas.contains(view.to_canvas({2, 1})));
  CHECK(xy(view.to_canvas({3, 0})) == std::pair(6, 2));  // one past the right edge
  CHECK_FALSE(canvas.contains(view.to_canvas({3, 0})));
  CHECK(xy(view.to_canvas({0, -3})) == std::pair(3, -1));  // one below the bottom row
  CHECK_FALSE(canvas.contains(view.to_canvas({0, -3})));
}

}  // namespace tri
