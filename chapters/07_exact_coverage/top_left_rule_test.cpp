// The top-left rule, one edge class at a time. Each case is a triangle with integer vertices and
// one pixel centre exactly on one of its edges, worked out by hand, plus the neighbour that shares
// that edge. The oracle and the fixed-point rasterizer must both give the centre to exactly the
// triangle the rule names, for either winding: dropping the rule for one edge class, or flipping
// which way a left edge runs, fails at least one of these tests.
#include <catch2/catch.hpp>

#include <array>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/fixed_point.hpp"

using tri::Triangle;

namespace {

// Whether draw paints pixel p of triangle t (on a canvas large enough for every case here).
bool draws(void (*draw)(tri::Canvas&, const Triangle&, tri::Color), const Triangle& t,
           glm::ivec2 p) {
  tri::Canvas canvas(16, 16);
  canvas.enable_write_counts();
  draw(canvas, t, tri::colors::white);
  return canvas.write_count(p.x, p.y) == 1;
}

// The same triangle, clockwise where t is counter-clockwise and vice versa.
Triangle reversed(const Triangle& t) {
  return {{t[0], t[2], t[1]}};
}

// Asserts the oracle's and the fixed-point rasterizer's decision on pixel p of t, both windings.
void check_decision(const Triangle& t, glm::ivec2 p, bool kept) {
  for (const Triangle& order : {t, reversed(t)}) {
    INFO("triangle (" << order[0].x << ", " << order[0].y << ") (" << order[1].x << ", "
                      << order[1].y << ") (" << order[2].x << ", " << order[2].y << "), pixel ("
                      << p.x << ", " << p.y << ")");
    CHECK(tri::ch07::oracle_covers(order, p) == kept);
    CHECK(draws(tri::ch07::draw_triangle_fixed_point_8, order, p) == kept);
  }
}

}  // namespace

TEST_CASE("A centre on a top edge belongs to the triangle below it, not to the one above",
          "[07_exact_coverage][step1]") {
  // (7,5) -> (1,5) is horizontal and runs right to left: the top edge of `below`. The same edge
  // runs left to right in `above`, where it is a bottom edge.
  const Triangle below{{{4, 1}, {7, 5}, {1, 5}}};
  const Triangle above{{{1, 5}, {7, 5}, {3, 8}}};
  check_decision(below, {3, 5}, true);
  check_decision(above, {3, 5}, false);
}

TEST_CASE("A centre on a left edge belongs to the triangle right of it, not to its neighbour",
          "[07_exact_coverage][step1]") {
  // (4,6) -> (2,2) runs downward through (3,4): the left edge of `right`. In `left` the same edge
  // runs upward, so there it is a right edge.
  const Triangle right{{{4, 6}, {2, 2}, {6, 2}}};
  const Triangle left{{{2, 2}, {4, 6}, {0, 6}}};
  check_decision(right, {3, 4}, true);
  check_decision(left, {3, 4}, false);
}

TEST_CASE("A centre on a right edge goes to the neighbour right of it, whose left edge it is",
          "[07_exact_coverage][step1]") {
  // (6,1) -> (8,7) runs upward through (7,4): a right edge of `left`, which does not get the
  // centre. `right` has the same edge running downward, a left edge, and gets it.
  const Triangle left{{{2, 4}, {6, 1}, {8, 7}}};
  const Triangle right{{{8, 7}, {6, 1}, {10, 3}}};
  check_decision(left, {7, 4}, false);
  check_decision(right, {7, 4}, true);
}

TEST_CASE("A centre on a bottom edge goes to the neighbour below it, whose top edge it is",
          "[07_exact_coverage][step1]") {
  // (2,3) -> (9,3) is horizontal and runs left to right: the bottom edge of `above`, which does
  // not get (6,3). In `below` it runs right to left, a top edge, and gets it.
  const Triangle above{{{2, 3}, {9, 3}, {5, 7}}};
  const Triangle below{{{9, 3}, {2, 3}, {4, 0}}};
  check_decision(above, {6, 3}, false);
  check_decision(below, {6, 3}, true);
}

TEST_CASE("Six triangles around a vertex give it and each centre on a spoke to one of them",
          "[07_exact_coverage][step1]") {
  // The fan of the rule diagram (07_top_left_rule): six triangles around V = (6,6), listed
  // counter-clockwise. Each spoke is top or left in exactly one of its two triangles; V goes to
  // the one triangle whose two edges at V are top and left: F, with (12,6) -> V on top and
  // V -> (10,2) running down on the left.
  const glm::dvec2 v{6, 6};
  const std::array<Triangle, 6> fan{{
      {{v, {12, 6}, {10, 10}}},  // A
      {{v, {10, 10}, {2, 10}}},  // B
      {{v, {2, 10}, {0, 6}}},    // C
      {{v, {0, 6}, {2, 2}}},     // D
      {{v, {2, 2}, {10, 2}}},    // E
      {{v, {10, 2}, {12, 6}}},   // F
  }};
  struct Owner {
    glm::ivec2 centre;
    int triangle;  // index into fan
  };
  const Owner owners[] = {
      // The shared vertex V: F.
      {{6, 6}, 5},
      // V - (12,6): the bottom edge of A, the top edge of F.
      {{7, 6}, 5},
      {{8, 6}, 5},
      {{9, 6}, 5},
      {{10, 6}, 5},
      {{11, 6}, 5},
      // V - (10,10): a left edge in A, a right edge in B.
      {{7, 7}, 0},
      {{8, 8}, 0},
      {{9, 9}, 0},
      // V - (2,10): a left edge in B, a right edge in C.
      {{5, 7}, 1},
      {{4, 8}, 1},
      {{3, 9}, 1},
      // V - (0,6): the bottom edge of C, the top edge of D.
      {{1, 6}, 3},
      {{2, 6}, 3},
      {{3, 6}, 3},
      {{4, 6}, 3},
      {{5, 6}, 3},
      // V - (2,2): a right edge in D, a left edge in E.
      {{5, 5}, 4},
      {{4, 4}, 4},
      {{3, 3}, 4},
      // V - (10,2): a right edge in E, a left edge in F.
      {{7, 5}, 5},
      {{8, 4}, 5},
      {{9, 3}, 5},
  };
  for (const Owner& owner : owners) {
    for (std::size_t i = 0; i < fan.size(); ++i) {
      check_decision(fan[i], owner.centre, static_cast<int>(i) == owner.triangle);
    }
  }
}

TEST_CASE("Without the tie rule both neighbours keep a centre on their shared edge",
          "[07_exact_coverage][top_left_rule]") {
  // The inclusive variant of the figures: every edge keeps its zeros, top-left or not.
  const std::array<std::array<Triangle, 2>, 4> pairs{{
      {{{{{4, 1}, {7, 5}, {1, 5}}}, {{{1, 5}, {7, 5}, {3, 8}}}}},
      {{{{{4, 6}, {2, 2}, {6, 2}}}, {{{2, 2}, {4, 6}, {0, 6}}}}},
      {{{{{2, 4}, {6, 1}, {8, 7}}}, {{{8, 7}, {6, 1}, {10, 3}}}}},
      {{{{{2, 3}, {9, 3}, {5, 7}}}, {{{9, 3}, {2, 3}, {4, 0}}}}},
  }};
  const glm::ivec2 centres[] = {{3, 5}, {3, 4}, {7, 4}, {6, 3}};
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    for (const Triangle& t : pairs[i]) {
      CHECK(draws(tri::ch07::draw_triangle_fixed_point_inclusive, t, centres[i]));
      CHECK(draws(tri::ch07::draw_triangle_fixed_point_inclusive, reversed(t), centres[i]));
    }
  }
}
