#include "measure/hard_cases.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include <glm/common.hpp>

namespace tri::hard_cases {
namespace {

constexpr int size = 32;
constexpr double unit = 1.0 / 256;

Scene scene_of(std::initializer_list<Triangle> triangles) {
  Scene scene;
  scene.width = size;
  scene.height = size;
  for (const Triangle& t : triangles)
    scene.primitives.emplace_back(SceneTriangle{t, colors::white});
  return scene;
}

// A grid of quads split in two, vertices at the given points (a shared-edge mesh).
Scene grid_mesh(double origin, double step, int cells, double jitter) {
  Scene scene = scene_of({});
  const auto point = [&](int i, int j) {
    // Deterministic jitter on the 1/256 grid, below 1/6 of a cell so no triangle folds over.
    const double jx = (i > 0 && i < cells) ? jitter * std::sin(i * 7.0 + j * 3.0) : 0;
    const double jy = (j > 0 && j < cells) ? jitter * std::cos(i * 5.0 + j * 11.0) : 0;
    return glm::dvec2(std::round((origin + i * step + jx) * 256) / 256,
                      std::round((origin + j * step + jy) * 256) / 256);
  };
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      scene.primitives.emplace_back(
          SceneTriangle{{point(i, j), point(i + 1, j), point(i + 1, j + 1)}, colors::white});
      scene.primitives.emplace_back(
          SceneTriangle{{point(i, j), point(i + 1, j + 1), point(i, j + 1)}, colors::white});
    }
  }
  return scene;
}

Scene fan(glm::dvec2 centre, double radius, int count, bool integer_rim) {
  Scene scene = scene_of({});
  std::vector<glm::dvec2> rim;
  for (int i = 0; i < count; ++i) {
    const double a = 2 * std::numbers::pi * i / count;
    glm::dvec2 p = centre + radius * glm::dvec2(std::cos(a), std::sin(a));
    p = integer_rim ? glm::round(p) : glm::round(p * 256.0) / 256.0;
    rim.push_back(p);
  }
  for (int i = 0; i < count; ++i) {
    scene.primitives.emplace_back(
        SceneTriangle{{centre, rim[i], rim[(i + 1) % count]}, colors::white});
  }
  return scene;
}

}  // namespace

std::vector<HardCase> all_cases() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const double big = 1073741824.0;  // 2^30
  std::vector<HardCase> cases{
      {"all_vertices_equal", "zero area: a point; nothing may be drawn",
       scene_of({{{{10, 10}, {10, 10}, {10, 10}}}})},
      {"two_vertices_equal", "zero area: a segment with a repeated end",
       scene_of({{{{5, 5}, {5, 5}, {25, 17}}}})},
      {"collinear_horizontal", "zero area on one row: the scanline's all-equal-y case",
       scene_of({{{{2, 8}, {26, 8}, {11, 8}}}})},
      {"collinear_vertical", "zero area on one column", scene_of({{{{9, 2}, {9, 27}, {9, 13}}}})},
      {"collinear_diagonal", "zero area along a slope through pixel centres",
       scene_of({{{{2, 3}, {22, 13}, {12, 8}}}})},
      {"horizontal_top_edge", "y1 == y2: a division by zero for the scanline's upper half",
       scene_of({{{{4, 24}, {28, 24}, {15, 4}}}})},
      {"horizontal_bottom_edge", "y0 == y1: a division by zero for the lower half",
       scene_of({{{{4, 4}, {28, 4}, {17, 25}}}})},
      {"needle_subpixel_height", "a long triangle less than a pixel tall",
       scene_of({{{{1.5, 10 + 64 * unit}, {30.5, 10 + 128 * unit}, {16, 10 + 192 * unit}}}})},
      {"sliver_across_centres", "a thin sliver along a diagonal row of centres",
       scene_of({{{{1, 1}, {29, 29}, {29 + 64 * unit, 29 - 64 * unit}}}})},
      {"subpixel_no_centre", "a triangle inside one pixel that covers no centre",
       scene_of({{{{5 + 26 * unit, 5 + 26 * unit},
                   {5 + 102 * unit, 5 + 26 * unit},
                   {5 + 51 * unit, 5 + 102 * unit}}}})},
      {"subpixel_one_centre", "a triangle of a fraction of a pixel around one centre",
       scene_of({{{{5 - 26 * unit, 5 - 26 * unit},
                   {5 + 51 * unit, 5 - 26 * unit},
                   {5, 5 + 51 * unit}}}})},
      {"centre_on_top_edge", "a 1/256 triangle whose top edge passes through a centre",
       scene_of({{{{7 + unit, 7}, {7 - unit, 7}, {7, 7 - unit}}}})},
      {"centre_on_bottom_edge", "a 1/256 triangle whose bottom edge passes through a centre",
       scene_of({{{{7 - unit, 7}, {7 + unit, 7}, {7, 7 + unit}}}})},
      {"edges_through_centres", "integer vertices: every edge passes through pixel centres",
       scene_of({{{{3, 3}, {27, 9}, {9, 27}}}})},
      {"right_triangle_on_centres", "legs along a row and a column of centres",
       scene_of({{{{2, 2}, {26, 2}, {2, 26}}}})},
      {"rectangle_split_in_two", "two triangles sharing a diagonal through centres",
       scene_of({{{{4, 4}, {28, 4}, {28, 28}}}, {{{4, 4}, {28, 28}, {4, 28}}}})},
      {"fan_integer", "16 triangles around a pixel centre, rim on pixel centres",
       fan({16, 16}, 13, 16, true)},
      {"fan_subpixel", "24 triangles around an off-grid centre",
       fan({15.6015625, 16.30078125}, 13.5, 24, false)},
      {"grid_mesh_integer", "a 6x6 grid of integer squares split in two: shared edges and vertices",
       grid_mesh(1, 5, 6, 0)},
      {"grid_mesh_jittered", "a jittered 7x7 grid mesh on the 1/256 grid",
       grid_mesh(0.5, 4.5, 7, 0.7)},
      {"vertex_far_1e5", "one vertex 1e5 pixels away", scene_of({{{{3, 4}, {1e5, 9}, {20, 30}}}})},
      {"vertex_far_1e7", "one vertex 1e7 pixels away",
       scene_of({{{{3, 4}, {-1e7, 2e7}, {28, 30}}}})},
      {"vertices_far_2p30", "two vertices at ±2^30 crossing the canvas",
       scene_of({{{{-big, 3}, {big, 17}, {16, 29}}}})},
      {"huge_covering_canvas", "vertices at ±2^30 whose triangle covers the whole canvas",
       scene_of({{{{-big, -big}, {big, -big}, {0, big}}}})},
      {"beyond_float_integers", "vertices past 2^24, where float can no longer hold every integer",
       scene_of({{{{16777217, 5}, {-16777215, 11}, {16, 29}}}})},
      {"clockwise_copy", "the same triangle in clockwise order",
       scene_of({{{{3, 3}, {9, 27}, {27, 9}}}})},
      {"translated_copies", "a triangle and its copy moved by whole pixels (7, 5)",
       scene_of({{{{2.25, 3.5}, {12.75, 6.125}, {5.5, 14}}},
                 {{{9.25, 8.5}, {19.75, 11.125}, {12.5, 19}}}})},
  };
  HardCase nan_case{"nan_vertex", "a NaN coordinate must be refused, not drawn",
                    scene_of({{{{3, 3}, {nan, 20}, {20, 3}}}}), true};
  HardCase inf_case{"infinite_vertex", "an infinite coordinate must be refused, not drawn",
                    scene_of({{{{3, 3}, {inf, 20}, {20, -inf}}}}), true};
  cases.push_back(nan_case);
  cases.push_back(inf_case);
  return cases;
}

Outcome run_case(const TriangleAlgorithm& algorithm, const HardCase& hard_case) {
  Outcome outcome;
  outcome.algorithm = std::string(algorithm.name);
  outcome.rule = std::string(rule_name(algorithm.rule));
  outcome.case_name = hard_case.name;
  outcome.error = measure_error(algorithm, hard_case.scene);
  std::size_t triangles = hard_case.scene.primitives.size();
  const bool rejection_right = hard_case.expect_rejection ? outcome.error.rejected == triangles
                                                          : outcome.error.rejected == 0;
  outcome.safe = outcome.error.outside_writes == 0 && rejection_right;
  return outcome;
}

std::vector<Outcome> run_all(const std::vector<TriangleAlgorithm>& algorithms) {
  std::vector<Outcome> outcomes;
  const auto cases = all_cases();
  for (const auto& algorithm : algorithms) {
    for (const auto& c : cases) outcomes.push_back(run_case(algorithm, c));
  }
  return outcomes;
}

std::string to_csv(const std::vector<Outcome>& outcomes) {
  std::ostringstream csv;
  csv << "algorithm,case,covered,missed,extra,gaps,overdraw,order_dependent,outside_writes,"
         "rejected\n";
  for (const auto& o : outcomes) {
    const ErrorReport& e = o.error;
    csv << o.algorithm << ',' << o.case_name << ',' << e.covered << ',' << e.missed << ','
        << e.extra << ',' << e.gaps << ',' << e.overdraw << ',' << e.order_dependent << ','
        << e.outside_writes << ',' << e.rejected << '\n';
  }
  return csv.str();
}

}  // namespace tri::hard_cases
