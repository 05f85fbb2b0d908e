#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"

using tri::Triangle;
using tri::ch08::RowSpan;
using tri::ch08::testing::grid_coordinate;

TEST_CASE("floor_div rounds toward minus infinity for every sign", "[08_fast_exact][traps]") {
  using tri::ch08::floor_div;
  CHECK(floor_div(7, 2) == 3);
  CHECK(floor_div(-7, 2) == -4);
  CHECK(floor_div(-8, 2) == -4);
  CHECK(floor_div(0, 5) == 0);
  CHECK(floor_div(-1, 1000000) == -1);
  CHECK(floor_div(std::int64_t{1} << 61, 3) == ((std::int64_t{1} << 61) / 3));
  tri::testing::Random random(17);
  for (int i = 0; i < 100000; ++i) {
    const std::int64_t a = random.integer(-1000000, 1000000);
    const std::int64_t b = random.integer(1, 1000);
    REQUIRE(floor_div(a, b) ==
            static_cast<std::int64_t>(std::floor(static_cast<double>(a) / static_cast<double>(b))));
  }
}

TEST_CASE("a row's span ends are exact: covered inside, uncovered just beyond, nothing else",
          "[08_fast_exact][step3]") {
  tri::testing::Random random(21);
  tri::ch08::testing::for_each_random_setup(
      random, 3000, 40, 37, [&](int i, const tri::ch08::TriangleSetup& setup) {
        const auto& r = setup.range;
        for (int y = r.min.y; y <= r.max.y; ++y) {
          const RowSpan span = tri::ch08::row_span(setup, y);
          for (int x = r.min.x; x <= r.max.x; ++x) {
            INFO("triangle " << i << " pixel " << x << "," << y);
            REQUIRE(setup.covers(x, y) == (x >= span.first && x <= span.last));
          }
          if (!span.empty()) {
            CHECK(span.first >= r.min.x);
            CHECK(span.last <= r.max.x);
          }
        }
      });
}

TEST_CASE("a horizontal edge limits the rows the walker visits", "[08_fast_exact][step3]") {
  // A bottom edge exactly on row 3 is not top-left: the walker starts one row higher.
  const auto bottom = tri::ch08::setup_triangle({{{2, 3}, {12, 3}, {7, 9}}}, 16, 16);
  REQUIRE(bottom);
  CHECK(bottom->range.min.y == 3);
  const tri::ch08::SpanWalker from_above(*bottom);
  CHECK(from_above.first_row() == 4);
  CHECK(from_above.last_row() == 9);
  // A top edge exactly on row 9 is top-left: its row is walked.
  const auto top = tri::ch08::setup_triangle({{{2, 9}, {12, 9}, {7, 3}}}, 16, 16);
  REQUIRE(top);
  const tri::ch08::SpanWalker to_the_top(*top);
  CHECK(to_the_top.first_row() == 3);
  CHECK(to_the_top.last_row() == 9);
}

namespace {

// The walker's spans, row by row (span, next_row) and in one pass (for_each_row), against
// row_span's on every row of the setup's range; rows it skips must be empty.
void check_walker(const tri::ch08::TriangleSetup& setup) {
  tri::ch08::SpanWalker walker(setup);
  int expected_y = walker.first_row();
  walker.for_each_row([&](int y, RowSpan walked) {
    const RowSpan direct = tri::ch08::row_span(setup, y);
    INFO("for_each_row, row " << y);
    REQUIRE(y == expected_y++);
    REQUIRE(walked.empty() == direct.empty());
    if (!direct.empty()) REQUIRE(walked == direct);
  });
  REQUIRE(expected_y == walker.last_row() + 1);
  for (int y = setup.range.min.y; y <= setup.range.max.y; ++y) {
    if (y < walker.first_row() || y > walker.last_row()) {
      INFO("row " << y << " skipped");
      REQUIRE(tri::ch08::row_span(setup, y).empty());
    }
  }
  for (int y = walker.first_row(); y <= walker.last_row(); ++y, walker.next_row()) {
    const RowSpan direct = tri::ch08::row_span(setup, y);
    const RowSpan walked = walker.span();
    INFO("row " << y);
    REQUIRE(walked.empty() == direct.empty());
    if (!direct.empty()) REQUIRE(walked == direct);
  }
}

// The walker on the setup, and on the setup clipped to a few boxes (tiles, bands, one row).
void check_walker_and_clips(const tri::ch08::TriangleSetup& setup, tri::testing::Random& random) {
  check_walker(setup);
  const auto& r = setup.range;
  for (int c = 0; c < 4; ++c) {
    const int x0 = static_cast<int>(random.integer(r.min.x, r.max.x));
    const int y0 = static_cast<int>(random.integer(r.min.y, r.max.y));
    const int w = c == 0 ? 8 : static_cast<int>(random.integer(1, 24));
    const int h = c == 1 ? 1 : static_cast<int>(random.integer(1, 24));
    const tri::ch05::PixelBox box{{x0, y0}, {x0 + w - 1, y0 + h - 1}};
    const auto clipped = tri::ch08::clip_setup(setup, box);
    if (!clipped) continue;
    INFO("clipped to " << box.min.x << "," << box.min.y << " - " << box.max.x << "," << box.max.y);
    check_walker(*clipped);
  }
}

// check_walker_and_clips on the triangle with its vertices in this order and in the reverse one
// (the setup turns a clockwise one around), mirrored in x, in y and across the diagonal: 16
// setups on a size x size canvas.
void check_every_orientation(const Triangle& t, int size, tri::testing::Random& random) {
  for (int m = 0; m < 8; ++m) {
    Triangle u = t;
    for (auto& v : u) {
      if (m & 1) v.x = size - 1 - v.x;
      if (m & 2) v.y = size - 1 - v.y;
      if (m & 4) std::swap(v.x, v.y);
    }
    for (int order = 0; order < 2; ++order) {
      if (order == 1) std::swap(u[1], u[2]);
      INFO("mirrored " << m << ", order " << order);
      if (const auto setup = tri::ch08::setup_triangle(u, size, size)) {
        check_walker_and_clips(*setup, random);
      }
    }
  }
}

}  // namespace

TEST_CASE("The division-free walker gives the direct span on every row", "[08_fast_exact][step3]") {
  tri::testing::Random random(22);
  tri::ch08::testing::for_each_random_setup(random, 3000, 64, 61,
                                            [&](int i, const tri::ch08::TriangleSetup& setup) {
                                              INFO("triangle " << i);
                                              check_walker_and_clips(setup, random);
                                            });
}

TEST_CASE("The walker hands a side over exactly at the middle vertex, on a pixel row or off it",
          "[08_fast_exact][step3]") {
  // The middle vertex on a pixel-centre row, 1/256 below or above it, and random; the other two
  // anywhere near (partly off) a 48 x 48 canvas, in every orientation.
  tri::testing::Random random(23);
  constexpr int size = 48;
  for (int i = 0; i < 1500; ++i) {
    const double row = static_cast<double>(random.integer(-2, size + 1));
    const double offsets[] = {0.0, -1.0 / 256, 1.0 / 256, grid_coordinate(random, -1, 1)};
    const double middle_y = row + offsets[i % 4];
    const Triangle t{{{grid_coordinate(random, -8, size + 8),
                       grid_coordinate(random, middle_y - size, middle_y - 1.0 / 256)},
                      {grid_coordinate(random, -8, size + 8),
                       grid_coordinate(random, middle_y + 1.0 / 256, middle_y + size)},
                      {grid_coordinate(random, -8, size + 8), middle_y}}};
    INFO("triangle " << i);
    check_every_orientation(t, size, random);
  }
}

TEST_CASE("The walker is exact on slivers of every orientation and with horizontal edges",
          "[08_fast_exact][step3]") {
  tri::testing::Random random(24);
  constexpr int size = 64;
  for (int i = 0; i < 600; ++i) {
    // A needle: a third vertex within a few 1/256 of the long edge, often on a pixel row.
    const glm::dvec2 a{grid_coordinate(random, -4, size + 4),
                       grid_coordinate(random, -4, size + 4)};
    const glm::dvec2 b{grid_coordinate(random, -4, size + 4),
                       grid_coordinate(random, -4, size + 4)};
    const glm::dvec2 on_line = a + random.real(0.05, 0.95) * (b - a);
    const double third_y = i % 2 == 0 ? std::round(on_line.y) : std::round(on_line.y * 256) / 256;
    const Triangle sliver{
        {a,
         b,
         {std::round(on_line.x * 256) / 256 + static_cast<double>(random.integer(-3, 3)) / 256,
          third_y}}};
    // A horizontal edge at the bottom or top, on a pixel row or between rows.
    const double edge_y = i % 3 == 0 ? std::round(a.y) : a.y;
    const Triangle flat{
        {{a.x, edge_y}, {b.x, edge_y}, {grid_coordinate(random, -4, size + 4), b.y}}};
    INFO("triangle " << i);
    check_every_orientation(sliver, size, random);
    check_every_orientation(flat, size, random);
  }
}

TEST_CASE("a sliver costs its rows: one short span per row instead of its bounding box",
          "[08_fast_exact][step3]") {
  // A needle from (2, 3) to (60, 40), a quarter of a pixel thick: a 59 x 38 bounding box.
  const Triangle sliver{{{2, 3}, {60, 40}, {31, 21.75}}};
  const auto setup = tri::ch08::setup_triangle(sliver, 64, 64);
  REQUIRE(setup);
  int rows = 0, pixels = 0, covered = 0;
  tri::ch08::SpanWalker walker(*setup);
  for (int y = walker.first_row(); y <= walker.last_row(); ++y, walker.next_row()) {
    ++rows;
    const RowSpan s = walker.span();
    if (!s.empty()) pixels += s.last - s.first + 1;
    CHECK(s.last - s.first + 1 <= 2);
    for (int x = setup->range.min.x; x <= setup->range.max.x; ++x) covered += setup->covers(x, y);
  }
  CHECK(rows == 38);
  CHECK(pixels == covered);
  CHECK(pixels > 0);
}

namespace {

// Fills count pixels from pixel `start` of a row of 300 and checks that exactly those changed.
template <int Bytes>
void check_fill_pixels_in(int start, int count) {
  const tri::Color background{1, 2, 3, 4}, fill{200, 100, 50, 255};
  std::vector<tri::Color> row(300, background);
  tri::ch08::fill_pixels_in<Bytes>(row.data() + start, count, std::bit_cast<std::uint32_t>(fill));
  for (int x = 0; x < static_cast<int>(row.size()); ++x) {
    INFO(Bytes << "-byte stores, start " << start << ", count " << count << ", pixel " << x);
    REQUIRE(row[static_cast<std::size_t>(x)] ==
            (x >= start && x < start + count ? fill : background));
  }
}

}  // namespace

TEST_CASE("fill_pixels_in writes exactly the span for every length, start and store width",
          "[08_fast_exact][step3]") {
  for (int start = 0; start < 20; ++start) {
    for (int count = 0; count <= 250; ++count) {
      check_fill_pixels_in<16>(start, count);
      check_fill_pixels_in<32>(start, count);
    }
  }
}

TEST_CASE("span_store_bytes is 32 on a host with AVX2 and 16 without", "[08_fast_exact][step3]") {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  const int expected = __builtin_cpu_supports("avx2") ? 32 : 16;
  CHECK(tri::ch08::span_store_bytes() == expected);
#else
  CHECK(tri::ch08::span_store_bytes() == 16);
#endif
}
