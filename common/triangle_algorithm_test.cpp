#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "common/scene.hpp"
#include "common/triangle_algorithm.hpp"
#include "tests/support/pixels.hpp"

namespace tri {
namespace {

using testing::PixelSet;

// Catch prints std::array and std::pair, not glm vectors, so those are compared instead.
std::array<int, 4> rgba(Color c) {
  return {c.r, c.g, c.b, c.a};
}
std::pair<int, int> xy(glm::ivec2 p) {
  return {p.x, p.y};
}

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double limit = 1073741824.0;  // 2^30

const Triangle ordinary = {glm::dvec2(1, 1), glm::dvec2(5, 1), glm::dvec2(1, 4)};

// The triangle with one of its six coordinates replaced.
Triangle with_coordinate(int index, double value) {
  Triangle t = ordinary;
  t[index / 2][index % 2] = value;
  return t;
}

// A stand-in algorithm: one pixel at the first vertex, so a test sees whether and with what it
// was called.
const TriangleAlgorithm one_pixel_algorithm{
    "one_pixel", "00_test", CoverageRule::approximate, "writes the pixel of the first vertex",
    [](Canvas& canvas, const Triangle& triangle, Color color) {
      canvas.put_pixel(nearest_pixel(triangle[0]), color);
    }};

// A stand-in renderer with state: it numbers the batches it draws (from 1) and marks triangle k
// of batch n at pixel (k, n), in the triangle's colour, so a test sees which renderer drew what.
class NumberingRenderer final : public BatchRenderer {
 public:
  void draw(Canvas& canvas, std::span<const SceneTriangle> triangles) override {
    ++batches_;
    for (std::size_t k = 0; k < triangles.size(); ++k)
      canvas.put_pixel({static_cast<int>(k), batches_}, triangles[k].color);
  }

 private:
  int batches_ = 0;
};

const TriangleAlgorithm numbering_algorithm{
    .name = "numbering",
    .chapter = "00_test",
    .rule = CoverageRule::approximate,
    .summary = "marks each triangle of each batch at (index in batch, batch number)",
    .draw = [](Canvas&, const Triangle&, Color) {},
    .make_renderer = []() -> std::unique_ptr<BatchRenderer> {
      return std::make_unique<NumberingRenderer>();
    }};

SceneTriangle scene_triangle(const Triangle& triangle, std::uint8_t red) {
  return {triangle, Color{red, 0, 0, 255}};
}

}  // namespace

TEST_CASE("The coverage rules are named top-left, inclusive and approximate",
          "[common][algorithm]") {
  CHECK(rule_name(CoverageRule::top_left) == "top-left");
  CHECK(rule_name(CoverageRule::inclusive) == "inclusive");
  CHECK(rule_name(CoverageRule::approximate) == "approximate");
  CHECK(rule_name(CoverageRule::area) == "area");
}

TEST_CASE("Each draw result is described in one line", "[common][algorithm]") {
  CHECK(describe(DrawResult::drawn) == "drawn");
  CHECK(describe(DrawResult::rejected_non_finite) ==
        "not drawn: a vertex coordinate is NaN or infinite");
  CHECK(describe(DrawResult::rejected_out_of_range) ==
        "not drawn: a vertex coordinate is outside ±2^30");
}

TEST_CASE("The triangle limit is the scene limit, 2^30", "[common][algorithm]") {
  CHECK(max_scene_coordinate == limit);
  CHECK(max_scene_coordinate == std::ldexp(1.0, 30));
}

TEST_CASE("validate_triangle accepts finite coordinates up to exactly plus or minus 2^30",
          "[common][algorithm][validate]") {
  CHECK(validate_triangle(ordinary) == DrawResult::drawn);
  CHECK(validate_triangle({glm::dvec2(0, 0), glm::dvec2(0, 0), glm::dvec2(0, 0)}) ==
        DrawResult::drawn);
  CHECK(validate_triangle({glm::dvec2(limit, -limit), glm::dvec2(-limit, limit),
                           glm::dvec2(limit, limit)}) == DrawResult::drawn);
  CHECK(validate_triangle({glm::dvec2(std::numeric_limits<double>::denorm_min(), -0.0),
                           glm::dvec2(1e-300, 0), glm::dvec2(0, 0)}) == DrawResult::drawn);
}

TEST_CASE("validate_triangle refuses NaN and infinities in any coordinate",
          "[common][algorithm][validate]") {
  for (int index = 0; index < 6; ++index) {
    INFO("coordinate " << index);
    CHECK(validate_triangle(with_coordinate(index, not_a_number)) ==
          DrawResult::rejected_non_finite);
    CHECK(validate_triangle(with_coordinate(index, -not_a_number)) ==
          DrawResult::rejected_non_finite);
    CHECK(validate_triangle(with_coordinate(index, infinity)) == DrawResult::rejected_non_finite);
    CHECK(validate_triangle(with_coordinate(index, -infinity)) == DrawResult::rejected_non_finite);
  }
}

TEST_CASE("validate_triangle refuses coordinates beyond plus or minus 2^30",
          "[common][algorithm][validate]") {
  const double just_above = std::nextafter(limit, infinity);
  for (int index = 0; index < 6; ++index) {
    INFO("coordinate " << index);
    CHECK(validate_triangle(with_coordinate(index, limit)) == DrawResult::drawn);
    CHECK(validate_triangle(with_coordinate(index, -limit)) == DrawResult::drawn);
    CHECK(validate_triangle(with_coordinate(index, just_above)) ==
          DrawResult::rejected_out_of_range);
    CHECK(validate_triangle(with_coordinate(index, -just_above)) ==
          DrawResult::rejected_out_of_range);
    CHECK(validate_triangle(with_coordinate(index, 1e300)) == DrawResult::rejected_out_of_range);
    CHECK(validate_triangle(with_coordinate(index, std::numeric_limits<double>::lowest())) ==
          DrawResult::rejected_out_of_range);
  }
}

TEST_CASE("A non-finite coordinate is reported before an out-of-range one",
          "[common][algorithm][validate]") {
  const Triangle both = {glm::dvec2(2 * limit, 0), glm::dvec2(0, 0), glm::dvec2(0, not_a_number)};
  CHECK(validate_triangle(both) == DrawResult::rejected_non_finite);
}

TEST_CASE("draw_triangle calls the algorithm once with the triangle and colour it was given",
          "[common][algorithm][draw]") {
  Canvas canvas(8, 8);
  canvas.enable_write_counts();
  const Triangle triangle = {glm::dvec2(3.4, 5.6), glm::dvec2(7, 0), glm::dvec2(0, 0)};
  CHECK(draw_triangle(one_pixel_algorithm, canvas, triangle, colors::yellow) == DrawResult::drawn);
  CHECK(testing::written_pixels(canvas) == PixelSet{{3, 6}});
  CHECK(canvas.write_count(3, 6) == 1);
  CHECK(rgba(canvas.pixel(3, 6)) == rgba(colors::yellow));
  CHECK(canvas.outside_writes() == 0);
}

TEST_CASE("draw_triangle draws nothing for a refused triangle and says why",
          "[common][algorithm][draw]") {
  struct Case {
    Triangle triangle;
    DrawResult expected;
  };
  const std::vector<Case> cases = {
      {with_coordinate(0, not_a_number), DrawResult::rejected_non_finite},
      {with_coordinate(3, infinity), DrawResult::rejected_non_finite},
      {with_coordinate(5, -infinity), DrawResult::rejected_non_finite},
      {with_coordinate(1, std::nextafter(limit, infinity)), DrawResult::rejected_out_of_range},
      {with_coordinate(4, -1e10), DrawResult::rejected_out_of_range},
      // The first vertex is fine; only another vertex is refused, yet nothing is drawn.
      {{glm::dvec2(2, 2), glm::dvec2(not_a_number, 0), glm::dvec2(0, 0)},
       DrawResult::rejected_non_finite},
      {{glm::dvec2(2, 2), glm::dvec2(0, 0), glm::dvec2(0, 1e12)},
       DrawResult::rejected_out_of_range},
  };
  for (const Case& c : cases) {
    Canvas canvas(8, 8);
    canvas.enable_write_counts();
    CHECK(draw_triangle(one_pixel_algorithm, canvas, c.triangle, colors::red) == c.expected);
    CHECK(testing::written_pixels(canvas).empty());
    CHECK(canvas.outside_writes() == 0);
  }
}

TEST_CASE("A batch drawer keeps the algorithm's renderer and hands it only accepted triangles",
          "[common][algorithm][draw]") {
  Canvas canvas(8, 8);
  canvas.enable_write_counts();
  BatchDrawer drawer(numbering_algorithm);
  const std::vector<SceneTriangle> first{scene_triangle(ordinary, 11), scene_triangle(ordinary, 12),
                                         scene_triangle(ordinary, 13)};
  const std::vector<SceneTriangle> second{
      scene_triangle(ordinary, 21), scene_triangle(with_coordinate(2, not_a_number), 22),
      scene_triangle(with_coordinate(1, 2 * limit), 23), scene_triangle(ordinary, 24)};
  CHECK(drawer.draw(canvas, first) == 0);
  CHECK(drawer.draw(canvas, second) == 2);
  CHECK(drawer.draw(canvas, std::span(first).first(1)) == 0);
  // One renderer drew the three batches (rows 1, 2, 3), without the refused triangles.
  CHECK(testing::written_pixels(canvas) ==
        PixelSet{{0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}, {0, 3}});
  CHECK(canvas.pixel(1, 2).r == 24);
  CHECK(canvas.pixel(0, 3).r == 11);
  // draw_triangles makes a drawer, and so a renderer, for each batch: both are batch 1.
  Canvas once(8, 8);
  CHECK(draw_triangles(numbering_algorithm, once, second) == 2);
  CHECK(draw_triangles(numbering_algorithm, once, std::span(first).first(1)) == 0);
  CHECK(once.pixel(0, 1).r == 11);
  CHECK(once.pixel(1, 1).r == 24);
  CHECK(rgba(once.pixel(0, 2)) == rgba(colors::black));
}

TEST_CASE(
    "A prepared batch keeps the accepted triangles in order and refuses what the drawer "
    "refuses",
    "[common][algorithm][draw]") {
  const std::vector<SceneTriangle> triangles{
      scene_triangle(ordinary, 31),
      scene_triangle(with_coordinate(0, not_a_number), 32),
      scene_triangle(with_coordinate(3, -infinity), 33),
      scene_triangle(ordinary, 34),
      scene_triangle(with_coordinate(1, std::nextafter(limit, infinity)), 35),
      scene_triangle(with_coordinate(4, -limit), 36),
      scene_triangle(with_coordinate(5, -1e12), 37)};
  const std::vector<DrawResult> expected{DrawResult::drawn,
                                         DrawResult::rejected_non_finite,
                                         DrawResult::rejected_non_finite,
                                         DrawResult::drawn,
                                         DrawResult::rejected_out_of_range,
                                         DrawResult::drawn,
                                         DrawResult::rejected_out_of_range};
  PreparedBatch added;
  for (std::size_t i = 0; i < triangles.size(); ++i) CHECK(added.add(triangles[i]) == expected[i]);
  const PreparedBatch prepared(triangles);
  for (const PreparedBatch* batch : {static_cast<const PreparedBatch*>(&added), &prepared}) {
    CHECK(batch->refused() == 4);
    REQUIRE(batch->triangles().size() == 3);
    CHECK(batch->triangles()[0].color.r == 31);
    CHECK(batch->triangles()[1].color.r == 34);
    CHECK(batch->triangles()[2].color.r == 36);
    CHECK(batch->triangles()[2].vertices[2].x == -limit);
  }
  // Drawn through a drawer: the renderer gets the accepted triangles as one batch, as the
  // unprepared draw of the same list gives them, and the count refused is the same.
  Canvas from_prepared(8, 8), from_list(8, 8);
  from_prepared.enable_write_counts();
  from_list.enable_write_counts();
  CHECK(BatchDrawer(numbering_algorithm).draw(from_prepared, prepared) == 4);
  CHECK(BatchDrawer(numbering_algorithm).draw(from_list, triangles) == 4);
  CHECK(testing::written_pixels(from_prepared) == PixelSet{{0, 1}, {1, 1}, {2, 1}});
  CHECK(testing::written_pixels(from_prepared) == testing::written_pixels(from_list));
  CHECK(from_prepared.pixel(1, 1).r == 34);
  CHECK(from_prepared.pixel(2, 1).r == 36);
  // An algorithm without batch entries draws the accepted triangles one by one.
  Canvas one_by_one(8, 8);
  one_by_one.enable_write_counts();
  CHECK(BatchDrawer(one_pixel_algorithm).draw(one_by_one, prepared) == 4);
  CHECK(testing::written_pixels(one_by_one) == PixelSet{{1, 1}});
  CHECK(one_by_one.pixel(1, 1).r == 36);
}

TEST_CASE(
    "A batch culled to a canvas leaves out only triangles whose box lies more than a pixel "
    "outside it, and refuses what the unculled batch refuses",
    "[common][algorithm][draw]") {
  // A canvas of 8 x 6 pixels: centres 0..7 and 0..5, kept within one pixel of them.
  const CanvasExtent extent{8, 6};
  const auto shifted = [](glm::dvec2 by) {
    Triangle t = ordinary;  // box 1..5 x 1..4
    for (glm::dvec2& v : t) v += by;
    return t;
  };
  const double just_over = std::nextafter(1.0, infinity) - 1.0;
  const std::vector<SceneTriangle> triangles{
      scene_triangle(ordinary, 1),                          // inside: kept
      scene_triangle(shifted({-6, 0}), 2),                  // right edge at -1: kept
      scene_triangle(shifted({-6 - 4 * just_over, 0}), 3),  // just beyond: culled
      scene_triangle(shifted({7, 0}), 4),                   // left edge at 8: kept
      scene_triangle(shifted({7.0001, 0}), 5),              // culled
      scene_triangle(shifted({0, -5}), 6),                  // top at -1: kept
      scene_triangle(shifted({0, -5.0001}), 7),             // culled
      scene_triangle(shifted({0, 5}), 8),                   // bottom at 6: kept
      scene_triangle(shifted({0, 5.0001}), 9),              // culled
      scene_triangle(shifted({1000, 1000}), 10),            // far away: culled
      scene_triangle(shifted({-limit + 5, 0}), 11),         // at -2^30: culled
      scene_triangle({glm::dvec2(-90, 1), glm::dvec2(90, 2), glm::dvec2(0, 3)}, 12),  // across
      scene_triangle({glm::dvec2(1000, 1), glm::dvec2(1001, not_a_number), glm::dvec2(1002, 3)},
                     13),  // NaN, the rest off the canvas: refused
      scene_triangle({glm::dvec2(1000, 1), glm::dvec2(2 * limit, 2), glm::dvec2(1002, 3)},
                     14),  // beyond 2^30 and off the canvas: refused
      scene_triangle({glm::dvec2(-infinity, 1), glm::dvec2(2, 2), glm::dvec2(3, 3)}, 15)};
  PreparedBatch unculled, added(extent);
  for (const SceneTriangle& t : triangles) {
    CAPTURE(static_cast<int>(t.color.r));
    const DrawResult expected = unculled.add(t);
    CHECK(added.add(t) == expected);
  }
  const PreparedBatch culled(triangles, extent);
  for (const PreparedBatch* batch : {static_cast<const PreparedBatch*>(&added), &culled}) {
    CHECK(batch->refused() == 3);
    CHECK(batch->refused() == unculled.refused());
    CHECK(batch->culled() == 6);
    std::vector<int> kept;
    for (const SceneTriangle& t : batch->triangles()) kept.push_back(t.color.r);
    CHECK(kept == std::vector<int>{1, 2, 4, 6, 8, 12});
  }
  CHECK(unculled.culled() == 0);
  CHECK(unculled.triangles().size() == 12);
  // Drawn only where it was culled for: that canvas or a smaller one, never a larger one.
  BatchDrawer drawer(one_pixel_algorithm);
  Canvas same(8, 6), smaller(3, 2), wider(9, 6), taller(8, 7);
  same.enable_write_counts();
  CHECK(drawer.draw(same, culled) == 3);
  CHECK(testing::written_pixels(same) == PixelSet{{1, 1}});
  CHECK(drawer.draw(smaller, culled) == 3);
  CHECK_THROWS_AS(drawer.draw(wider, culled), std::invalid_argument);
  CHECK_THROWS_AS(drawer.draw(taller, culled), std::invalid_argument);
  CHECK(drawer.draw(wider, unculled) == 3);
}

TEST_CASE("nearest_pixel rounds to the nearest pixel centre, halves up",
          "[common][algorithm][round]") {
  struct Case {
    double value;
    int expected;
  };
  const Case cases[] = {
      {0.0, 0},
      {-0.0, 0},
      {0.5, 1},
      {-0.5, 0},
      {1.5, 2},
      {-1.5, -1},
      {2.5, 3},
      {-2.5, -2},
      {2.49, 2},
      {2.51, 3},
      {-2.49, -2},
      {-2.51, -3},
      {0.49999999999999994, 0},  // the largest double below 0.5: floor(x + 0.5) would give 1
      {-0.49999999999999994, 0},
      {std::nextafter(0.5, 1.0), 1},
      {std::nextafter(-0.5, -1.0), -1},
      {1e-300, 0},
      {-1e-300, 0},
      {1000000000.4, 1000000000},
      {1000000000.5, 1000000001},
      {-1000000000.5, -1000000000},
      {limit - 0.5, 1073741824},
      {limit - 0.75, 1073741823},
      {std::nextafter(limit - 0.5, 0.0), 1073741823},
      {limit, 1073741824},
      {-limit, -1073741824},
      {-limit + 0.5, -1073741823},
      {-limit + 0.25, -1073741824},
  };
  for (const Case& c : cases) {
    INFO(std::hexfloat << c.value);
    CHECK(xy(nearest_pixel({c.value, 0.0})) == std::pair(c.expected, 0));
    CHECK(xy(nearest_pixel({0.0, c.value})) == std::pair(0, c.expected));
  }
  CHECK(xy(nearest_pixel({3.5, -7.5})) == std::pair(4, -7));
}

// An article-style fill that marks its three vertices only, to see what it was handed.
void mark_vertices(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, Color color) {
  for (const glm::ivec2 p : {a, b, c}) canvas.put_pixel(p, color);
}

TEST_CASE("draw_at_nearest_pixels hands the fill each vertex rounded to its nearest centre",
          "[common][algorithm][round]") {
  Canvas canvas(16, 16);
  canvas.enable_write_counts();
  draw_at_nearest_pixels<mark_vertices>(canvas, {{{2.5, 3.49}, {10.2, 0.5}, {-0.5, 14.51}}},
                                        colors::white);
  CHECK(testing::written_pixels(canvas) == PixelSet{{3, 3}, {10, 1}, {0, 15}});
}

TEST_CASE("nearest_pixel is never more than half a pixel away, on random points",
          "[common][algorithm][round]") {
  testing::Random random(7);
  for (int trial = 0; trial < 2000; ++trial) {
    const double range = trial < 1000 ? 100.0 : limit;
    const glm::dvec2 p{random.real(-range, range), random.real(-range, range)};
    const glm::ivec2 n = nearest_pixel(p);
    INFO(std::hexfloat << p.x << ", " << p.y);
    // p - n is exact here: p and n are within half a unit and of the same sign or both small.
    CHECK(p.x - n.x >= -0.5);
    CHECK(p.x - n.x < 0.5);
    CHECK(p.y - n.y >= -0.5);
    CHECK(p.y - n.y < 0.5);
  }
}

}  // namespace tri
