// Step 8: the narrow canvases hold exactly the pixels the RGBA8 canvas gets from the same
// traversal, for one triangle and for a scene of overlapping ones.
#include <catch2/catch.hpp>

#include <array>
#include <vector>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/08_fast_exact/narrow_canvases.hpp"
#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"
#include "tests/support/pixels.hpp"

using tri::Canvas;
using tri::Triangle;
using tri::ch08::IndexCanvas;
using tri::ch08::MaskCanvas;

namespace {

constexpr tri::Color background{9, 9, 9, 255};

// Canvas sizes whose rows end inside a 64-bit word, and one that spans several words.
constexpr std::array<glm::ivec2, 3> sizes{{{45, 37}, {21, 19}, {130, 23}}};

}  // namespace

TEST_CASE("One byte and one bit per pixel hold exactly the oracle's pixels of each triangle",
          "[08_fast_exact][step8]") {
  tri::testing::Random random(77);
  for (int i = 0; i < 1200; ++i) {
    const glm::ivec2 size = sizes[static_cast<std::size_t>(i) % sizes.size()];
    const Triangle t =
        tri::ch08::testing::random_triangle(random, tri::ch08::testing::shape_number(i), 40);
    INFO("triangle " << i << ": " << t[0].x << "," << t[0].y << " " << t[1].x << "," << t[1].y
                     << " " << t[2].x << "," << t[2].y);
    Canvas truth(size.x, size.y, background);
    tri::ch07::draw_triangle_oracle(truth, t, tri::colors::white);
    IndexCanvas indices(size.x, size.y);
    tri::ch08::draw_triangle_spans_index8(indices, t, 7);
    MaskCanvas mask(size.x, size.y);
    tri::ch08::draw_triangle_spans_mask1(mask, t);
    for (int y = 0; y < size.y; ++y) {
      for (int x = 0; x < size.x; ++x) {
        const bool covered = truth.pixel(x, y) == tri::colors::white;
        REQUIRE(indices.index(x, y) == (covered ? 7 : 0));
        REQUIRE(mask.covered(x, y) == covered);
      }
    }
  }
}

TEST_CASE("A palette index canvas of overlapping triangles reads back as the RGBA8 canvas",
          "[08_fast_exact][step8]") {
  // Later triangles cover earlier ones in both; the palette turns indices into the same colours.
  tri::testing::Random random(78);
  std::vector<tri::Color> palette{background};
  Canvas colors(130, 61, background);
  IndexCanvas indices(130, 61);
  for (int i = 0; i < 200; ++i) {
    const Triangle t =
        tri::ch08::testing::random_triangle(random, tri::ch08::testing::shape_number(i), 60);
    palette.push_back(tri::Color{static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(3 * i),
                                 static_cast<std::uint8_t>(255 - i), 255});
    tri::ch08::draw_triangle_spans(colors, t, palette.back());
    tri::ch08::draw_triangle_spans_index8(indices, t, static_cast<std::uint8_t>(i + 1));
  }
  int drawn = 0;
  for (int y = 0; y < colors.height(); ++y) {
    for (int x = 0; x < colors.width(); ++x) {
      REQUIRE(palette[indices.index(x, y)] == colors.pixel(x, y));
      drawn += indices.index(x, y) != 0;
    }
  }
  CHECK(drawn > 1000);  // the scene covers much of the canvas, so the comparison is not empty
}

TEST_CASE("A span of the mask sets exactly its bits, within one word and across words",
          "[08_fast_exact][step8]") {
  // Spans within a word, across one boundary and across several, ending at the row's end, in
  // each row of a canvas of two, on rows of whole words and on rows that end inside a word: the
  // other row keeps every bit clear.
  for (const auto& [width, begin, end] : std::vector<std::array<int, 3>>{
           {256, 0, 1},     {256, 3, 9},     {256, 60, 70},   {256, 63, 64},   {256, 64, 65},
           {256, 1, 200},   {256, 0, 256},   {256, 127, 129}, {256, 7, 64},    {256, 7, 65},
           {256, 250, 256}, {256, 199, 256}, {256, 198, 256}, {256, 190, 256}, {70, 0, 70},
           {70, 13, 70},    {70, 69, 70},    {70, 60, 68},    {130, 71, 128},  {130, 72, 130}}) {
    for (int y = 0; y < 2; ++y) {
      CAPTURE(width, begin, end, y);
      MaskCanvas mask(width, 2);
      tri::ch08::MaskWriter writer(mask);
      writer.span(y, begin, end);
      for (int x = 0; x < width; ++x) {
        REQUIRE(mask.covered(x, y) == (begin <= x && x < end));
        REQUIRE_FALSE(mask.covered(x, 1 - y));
      }
    }
  }
}

TEST_CASE("A triangle at most 32 pixels wide reaches the mask in lanes at every alignment and edge",
          "[08_fast_exact][step8]") {
  // Vertices on the quarter-pixel grid inside boxes of 8, 16, 24 and 32 columns of pixel centres
  // (each number of lanes), 2 to 20 rows high, at every column of canvases whose rows end inside a
  // word, at a word's end and across two words, with boxes hanging over each side: ties on edges
  // through pixel centres, rows crossing a word boundary, ranges clipped by the canvas. Each
  // triangle alone, against the oracle, in every copy the host runs.
  tri::testing::Random random(81);
  int drawn = 0, triangles = 0;
  for (const glm::ivec2 size : {glm::ivec2{70, 21}, glm::ivec2{64, 9}, glm::ivec2{130, 12}}) {
    for (int x0 = -31; x0 < size.x; ++x0) {
      for (const int y0 : {-7, -2, 0, 3, size.y - 8, size.y - 3, size.y - 1}) {
        for (int k = 0; k < 8; ++k) {
          const int columns = 8 * (k % 4 + 1), rows = random.integer(2, 20);
          Triangle t;
          for (auto& v : t) {
            v = {x0 + random.integer(0, 4 * (columns - 1)) / 4.0,
                 y0 + random.integer(0, 4 * (rows - 1)) / 4.0};
          }
          const auto setup = tri::ch08::setup_triangle(t, size.x, size.y);
          if (!setup) continue;
          INFO("triangle " << t[0].x << "," << t[0].y << " " << t[1].x << "," << t[1].y << " "
                           << t[2].x << "," << t[2].y << " on " << size.x << "x" << size.y);
          REQUIRE(tri::ch08::fits_mask_lanes(*setup));
          ++triangles;
          Canvas truth(size.x, size.y, background);
          tri::ch07::draw_triangle_oracle(truth, t, tri::colors::white);
          for (const auto set : tri::ch08::all_instruction_sets) {
            if (!tri::ch08::host_runs(set)) continue;
            CAPTURE(static_cast<int>(set));
            MaskCanvas mask(size.x, size.y);
            tri::ch08::fill_mask_lanes(mask, *setup, set);
            int off = 0;
            for (int y = 0; y < size.y; ++y) {
              for (int x = 0; x < size.x; ++x) {
                const bool covered = truth.pixel(x, y) == tri::colors::white;
                off += mask.covered(x, y) != covered;
                drawn += covered;
              }
            }
            REQUIRE(off == 0);
          }
        }
      }
    }
  }
  CHECK(triangles > 8000);
  CHECK(drawn > 50000);  // the comparisons are not of empty canvases
}
