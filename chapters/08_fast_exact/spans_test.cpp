#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/test_triangles.hpp"

using tri::Triangle;
using tri::ch08::RowSpan;

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

TEST_CASE("The division-free walker gives the direct span on every row", "[08_fast_exact][step3]") {
  tri::testing::Random random(22);
  tri::ch08::testing::for_each_random_setup(
      random, 3000, 64, 61, [&](int i, const tri::ch08::TriangleSetup& setup) {
        tri::ch08::SpanWalker walker(setup);
        // Rows a horizontal edge excludes are skipped: their direct spans are empty.
        for (int y = setup.range.min.y; y <= setup.range.max.y; ++y) {
          if (y < walker.first_row() || y > walker.last_row()) {
            INFO("triangle " << i << " row " << y << " skipped");
            REQUIRE(tri::ch08::row_span(setup, y).empty());
          }
        }
        for (int y = walker.first_row(); y <= walker.last_row(); ++y, walker.next_row()) {
          const RowSpan direct = tri::ch08::row_span(setup, y);
          const RowSpan walked = walker.span();
          INFO("triangle " << i << " row " << y);
          REQUIRE(walked.empty() == direct.empty());
          if (!direct.empty()) REQUIRE(walked == direct);
        }
      });
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
