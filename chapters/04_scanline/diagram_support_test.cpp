// The pixel claims the README reads off the step diagrams of the green triangle.
#include <catch2/catch.hpp>

#include "chapters/03_interpolate_fill/diagram_support.hpp"
#include "chapters/04_scanline/boundaries.hpp"
#include "chapters/04_scanline/diagram_support.hpp"
#include "chapters/04_scanline/lower_half.hpp"

using namespace tri::ch04;
using namespace tri::ch04::figures;

TEST_CASE("On the green triangle the +1 leaves B's last lower-half point at x = 126, not 120",
          "[04_scanline][step3][figures]") {
  const auto [a, b, c] = diagram_triangle().vertices;
  const SortedTriangle t = sort_by_y(a, b, c);
  REQUIRE(t.p1 == glm::ivec2(120, 160));
  CHECK(lower_half_ends(t, t.p1.y).b == 126);
}

TEST_CASE("The green triangle's lower half leaves out 35 centres that lie inside it",
          "[04_scanline][step4][figures]") {
  const auto [a, b, c] = diagram_triangle().vertices;
  const SortedTriangle t = sort_by_y(a, b, c);
  const tri::Canvas drawn =
      drawn_by([](tri::Canvas& canvas, glm::ivec2 p, glm::ivec2 q,
                  glm::ivec2 r) { fill_lower_half(canvas, p, q, r, tri::colors::white); },
               diagram_triangle());
  int left_out = 0, drawn_outside_rows = 0;
  for (int y = 0; y < drawn.height(); ++y) {
    for (int x = 0; x < drawn.width(); ++x) {
      const bool in_rows = y >= t.p0.y && y <= t.p1.y;
      if (!in_rows && drawn.write_count(x, y) > 0) ++drawn_outside_rows;
      if (in_rows && drawn.write_count(x, y) == 0 &&
          tri::ch03::figures::centre_in_triangle(a, b, c, {x, y})) {
        ++left_out;
        CHECK(x < lower_half_ends(t, y).b);  // all left of B's point: B lags, A loses none
      }
    }
  }
  CHECK(left_out == 35);
  CHECK(drawn_outside_rows == 0);
}
