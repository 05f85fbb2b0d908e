#include <climits>

#include <catch2/catch.hpp>

#include "chapters/05_edge_function/bounding_box.hpp"

using tri::ch05::bounding_box_on_canvas;
using tri::ch05::PixelBox;

namespace {

constexpr int two_to_30 = 1 << 30;

void require_box(const PixelBox& box, glm::ivec2 min, glm::ivec2 max) {
  CHECK(box.min == min);
  CHECK(box.max == max);
}

}  // namespace

TEST_CASE("The bounding box of a triangle on the canvas spans its vertices, ends included",
          "[05_edge_function][step1][bounding box]") {
  const PixelBox box = bounding_box_on_canvas({3, 4}, {10, 2}, {7, 9}, 20, 20);
  require_box(box, {3, 2}, {10, 9});
  CHECK_FALSE(box.empty());
}

TEST_CASE("The bounding box is clamped to the canvas on every side",
          "[05_edge_function][step1][bounding box]") {
  require_box(bounding_box_on_canvas({-5, 3}, {25, 8}, {10, 40}, 20, 30), {0, 3}, {19, 29});
  require_box(bounding_box_on_canvas({4, -7}, {6, 2}, {5, 3}, 20, 30), {4, 0}, {6, 3});
}

TEST_CASE("A triangle entirely off the canvas has an empty bounding box",
          "[05_edge_function][step1][bounding box]") {
  CHECK(bounding_box_on_canvas({-10, 2}, {-1, 5}, {-4, 9}, 20, 20).empty());  // left
  CHECK(bounding_box_on_canvas({20, 2}, {30, 5}, {24, 9}, 20, 20).empty());   // right
  CHECK(bounding_box_on_canvas({2, -9}, {8, -1}, {5, -3}, 20, 20).empty());   // below
  CHECK(bounding_box_on_canvas({2, 20}, {8, 25}, {5, 40}, 20, 20).empty());   // above
  // Off to the left but spanning the canvas vertically: still empty, not squashed to column 0.
  const PixelBox box = bounding_box_on_canvas({-30, -50}, {-2, 60}, {-9, 4}, 20, 20);
  CHECK(box.empty());
  CHECK(box.max.x == -2);
}

TEST_CASE("Vertices at plus or minus 2^30 give a box no larger than the canvas",
          "[05_edge_function][step1][bounding box][huge]") {
  require_box(bounding_box_on_canvas({-two_to_30, -two_to_30}, {two_to_30, -two_to_30},
                                     {0, two_to_30}, 16, 8),
              {0, 0}, {15, 7});
  // Only min, max and clamping: even the extremes of int cannot overflow.
  require_box(bounding_box_on_canvas({INT_MIN, INT_MIN}, {INT_MAX, 3}, {0, INT_MAX}, 16, 8), {0, 0},
              {15, 7});
}

TEST_CASE("A zero-area triangle's box is the box of its segment or its single point",
          "[05_edge_function][step1][bounding box][degenerate]") {
  require_box(bounding_box_on_canvas({0, 0}, {10, 10}, {20, 20}, 32, 32), {0, 0}, {20, 20});
  require_box(bounding_box_on_canvas({5, 6}, {5, 6}, {5, 6}, 32, 32), {5, 6}, {5, 6});
}
