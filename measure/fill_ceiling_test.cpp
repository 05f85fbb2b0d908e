// The ceiling's fills are checked by what they write; no test reads a clock's value.
#include <algorithm>
#include <functional>
#include <vector>

#include <catch2/catch.hpp>

#include "common/color.hpp"
#include "measure/fill_ceiling.hpp"

using tri::Canvas;
using tri::CeilingFill;
using tri::Color;

namespace {

bool one_color(const Canvas& canvas) {
  const auto pixels = canvas.pixels();
  return std::all_of(pixels.begin(), pixels.end(), [&](Color c) { return c == pixels.front(); });
}

}  // namespace

TEST_CASE("Each ceiling fill writes every pixel of the canvas, in one thread or several, and a "
          "new value every time",
          "[measure][fill_ceiling]") {
  for (const CeilingFill fill : tri::ceiling_fills) {
    for (const int threads : {1, 3, 64}) {
      CAPTURE(tri::name_of(fill), threads);
      Canvas canvas(13, 5, tri::colors::black);  // 13: rows end in a partial 8-pixel store
      const std::function<void()> run = tri::ceiling_fill_run(canvas, fill, threads);
      run();
      const Color first = canvas.pixel(0, 0);
      CHECK(first != tri::colors::black);
      CHECK(one_color(canvas));
      run();
      CHECK(canvas.pixel(12, 4) != first);
      CHECK(one_color(canvas));
      CHECK(canvas.outside_writes() == 0);
    }
  }
}

TEST_CASE("The ceiling is the faster of the two fills, in Mpixels per second",
          "[measure][fill_ceiling]") {
  tri::Timing memset, stores;
  memset.seconds.median = 0.5;  // 2e6 pixels in 0.5 s: 4 Mpix/s
  stores.seconds.median = 0.25;
  const tri::FillCeiling ceiling = tri::fill_ceiling_of(2e6, memset, stores);
  CHECK(ceiling.memset_mpix_per_s == 4.0);
  CHECK(ceiling.vector_stores_mpix_per_s == 8.0);
  CHECK(ceiling.mpix_per_s() == 8.0);
  CHECK(tri::name_of(CeilingFill::memset) == "memset");
  CHECK(tri::name_of(CeilingFill::vector_stores) == "vector stores");
}
