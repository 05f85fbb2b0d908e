#include "chapters/11_your_rasterizer/named_tests.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <variant>

#include <glm/common.hpp>

#include "common/random.hpp"
#include "measure/hard_cases.hpp"
#include "measure/scene_generators.hpp"

namespace tri::conformance {
namespace {

constexpr double unit = 1.0 / 256;    // the 1/256 grid: 8 bits of sub-pixel precision
constexpr double big = 1073741824.0;  // 2^30, the scene format's limit

Scene scene_of(int width, int height, const std::vector<Triangle>& triangles) {
  Scene scene;
  scene.width = width;
  scene.height = height;
  for (const auto& t : triangles) scene.primitives.emplace_back(SceneTriangle{t, colors::white});
  return scene;
}

glm::dvec2 on_grid(glm::dvec2 p) {
  return {snap_to_grid(p.x, 8), snap_to_grid(p.y, 8)};
}

// A grid of nx x ny square cells from origin, each split along a diagonal that alternates from
// cell to cell, so the mesh has shared edges of three directions and shared vertices.
std::vector<Triangle> grid_mesh(glm::dvec2 origin, double cell, int nx, int ny) {
  std::vector<Triangle> triangles;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const glm::dvec2 a = origin + cell * glm::dvec2(i, j), b = a + glm::dvec2(cell, 0),
                       c = a + glm::dvec2(cell, cell), d = a + glm::dvec2(0, cell);
      if ((i + j) % 2 == 0) {
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
      } else {
        triangles.push_back({a, b, d});
        triangles.push_back({b, c, d});
      }
    }
  }
  return triangles;
}

// n triangles around a shared centre, their rim points shared by neighbours.
std::vector<Triangle> fan(glm::dvec2 centre, double radius, int n, int grid_bits) {
  std::vector<glm::dvec2> rim;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * i / n;
    const glm::dvec2 p = centre + radius * glm::dvec2(std::cos(angle), std::sin(angle));
    rim.push_back({snap_to_grid(p.x, grid_bits), snap_to_grid(p.y, grid_bits)});
  }
  std::vector<Triangle> triangles;
  for (int i = 0; i < n; ++i) triangles.push_back(Triangle{centre, rim[i], rim[(i + 1) % n]});
  return triangles;
}

// The six orders of three vertices: three rotations of each winding.
constexpr std::array<std::array<int, 3>, 6> vertex_orders{
    {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};

Scene reordered(const Scene& scene, std::size_t order) {
  Scene out = scene;
  for (auto& primitive : out.primitives) {
    if (auto* t = std::get_if<SceneTriangle>(&primitive)) {
      const Triangle v = t->vertices;
      for (std::size_t i = 0; i < 3; ++i) {
        t->vertices[i] = v[static_cast<std::size_t>(vertex_orders[order][i])];
      }
    }
  }
  return out;
}

Scene moved(const Scene& scene, glm::dvec2 shift) {
  Scene out = scene;
  for (auto& primitive : out.primitives) {
    if (auto* t = std::get_if<SceneTriangle>(&primitive)) {
      for (auto& v : t->vertices) v += shift;
    }
  }
  return out;
}

// Seeded random triangles on a side x side canvas (measure/scene_generators.hpp).
Scene random_scene(int side, int triangles, double min_extent, double max_extent, int grid_bits,
                   std::uint64_t seed) {
  return generate_scene({.kind = SceneRecipe::Kind::random,
                         .width = side,
                         .height = side,
                         .triangles = triangles,
                         .min_extent = min_extent,
                         .max_extent = max_extent,
                         .grid_bits = grid_bits,
                         .seed = seed});
}

TestCase make_case(std::string label, Scene scene, Check check = Check::rule,
                   std::optional<Relation> same_as = std::nullopt) {
  TestCase test_case;
  test_case.label = std::move(label);
  test_case.scene = std::move(scene);
  test_case.check = check;
  test_case.same_as = same_as;
  return test_case;
}

TestCase bad_input_case(std::string label, Scene scene) {
  TestCase test_case = make_case(std::move(label), std::move(scene));
  test_case.bad_input = true;
  return test_case;
}

NamedTest hard_cases_test() {
  NamedTest test{"hard_cases",
                 "the book's hard cases (zero area, flat edges, slivers, ties, meshes, far "
                 "vertices) drawn pixel for pixel as the rule says",
                 {}};
  for (auto& hard_case : hard_cases::all_cases()) {
    // The NaN and infinite cases belong to bad_input, so that a crash there fails that test only.
    if (hard_case.expect_rejection) continue;
    test.cases.push_back(make_case(hard_case.name, std::move(hard_case.scene)));
  }
  return test;
}

NamedTest random_triangles_test() {
  NamedTest test{"random_triangles",
                 "random triangles with vertices on the 1/256 grid, from sub-pixel to the size of "
                 "the canvas, drawn pixel for pixel as the rule says",
                 {}};
  const std::array<std::pair<double, double>, 5> extents{
      {{0.05, 0.5}, {0.5, 2}, {2, 8}, {8, 24}, {24, 64}}};
  std::uint64_t seed = 2601;
  for (const auto& [low, high] : extents) {
    test.cases.push_back(make_case(
        "extent " + std::to_string(low).substr(0, 4) + " to " + std::to_string(high).substr(0, 4),
        random_scene(64, high < 1 ? 600 : 200, low, high, 8, seed++)));
  }
  return test;
}

NamedTest watertight_test() {
  NamedTest test{"watertight_meshes",
                 "meshes (grids, fans, jittered grids; vertices on and off pixel centres) write "
                 "every pixel inside them exactly once: no holes, no double writes",
                 {}};
  const auto add = [&test](std::string label, Scene scene) {
    test.cases.push_back(make_case(std::move(label), std::move(scene), Check::consistent));
  };
  add("grid on pixel centres", scene_of(40, 40, grid_mesh({2, 2}, 4, 9, 9)));
  add("grid off pixel centres", scene_of(40, 40, grid_mesh({2.5, 2.5}, 4, 9, 9)));
  add("grid on the 1/256 grid",
      scene_of(40, 40, grid_mesh({2 + 37 * unit, 1 + 211 * unit}, 3 + 91 * unit, 11, 11)));
  add("fan around a pixel centre", scene_of(40, 40, fan({20, 20}, 17, 20, 0)));
  add("fan around an off-centre point",
      scene_of(40, 40, fan({19 + 77 * unit, 20 + 130 * unit}, 17, 28, 8)));
  std::uint64_t seed = 2611;
  for (const int bits : {0, 8}) {
    add("jittered grid, grid bits " + std::to_string(bits),
        generate_scene({.kind = SceneRecipe::Kind::jittered_grid,
                        .width = 40,
                        .height = 40,
                        .triangles = 120,
                        .grid_bits = bits,
                        .seed = seed++}));
  }
  return test;
}

NamedTest tie_rule_test() {
  NamedTest test{"tie_rule",
                 "pixel centres exactly on horizontal and slanted edges and on shared vertices "
                 "belong to the triangle the rule names, and to that one only",
                 {}};
  const auto add = [&test](std::string label, std::vector<Triangle> triangles) {
    test.cases.push_back(make_case(std::move(label), scene_of(24, 24, triangles)));
  };
  add("flat top on centres", {{{{3, 16}, {19, 16}, {11, 4}}}});
  add("flat bottom on centres", {{{{3, 4}, {19, 4}, {11, 18}}}});
  add("slanted edges through centres", {{{{2, 2}, {8, 20}, {20, 8}}}});
  add("right triangle, legs on centres", {{{{3, 3}, {18, 3}, {3, 18}}}});
  add("right triangle, legs on centres, mirrored", {{{{20, 20}, {5, 20}, {20, 5}}}});
  add("1/256 triangle, centre on its top edge", {{{{7 + unit, 7}, {7 - unit, 7}, {7, 7 - unit}}}});
  add("1/256 triangle, centre on its bottom edge",
      {{{{7 - unit, 7}, {7 + unit, 7}, {7, 7 + unit}}}});
  add("square split along a diagonal",
      {{{{3, 3}, {19, 3}, {19, 19}}}, {{{3, 3}, {19, 19}, {3, 19}}}});
  add("two triangles sharing a horizontal edge",
      {{{{4, 11}, {18, 11}, {10, 2}}}, {{{4, 11}, {10, 20}, {18, 11}}}});
  add("two triangles sharing a vertical edge",
      {{{{11, 3}, {11, 19}, {3, 12}}}, {{{11, 3}, {19, 10}, {11, 19}}}});
  add("eight triangles sharing a vertex on a centre", fan({12, 12}, 9, 8, 0));
  return test;
}

NamedTest vertex_order_test() {
  NamedTest test{
      "vertex_order", "the six vertex orders (both windings) of a scene give the same pixels", {}};
  std::vector<std::pair<std::string, Scene>> bases{
      {"integer triangles", random_scene(32, 40, 1, 12, 0, 2621)},
      {"1/256 triangles", random_scene(32, 40, 0.5, 12, 8, 2622)},
      {"flat and shared edges", scene_of(24, 24, grid_mesh({2, 2}, 5, 4, 4))},
  };
  for (auto& [label, scene] : bases) {
    const std::size_t base = test.cases.size();
    for (std::size_t order = 0; order < vertex_orders.size(); ++order) {
      test.cases.push_back(make_case(
          label + ", order " + std::to_string(order + 1), reordered(scene, order), Check::relation,
          order == 0 ? std::nullopt : std::optional<Relation>(Relation{base, {0, 0}})));
    }
  }
  return test;
}

NamedTest translation_test() {
  NamedTest test{"translation", "a scene moved by whole pixels gives the same pixels, moved", {}};
  std::uint64_t seed = 2631;
  for (const int bits : {0, 8}) {
    // Vertices within 16..48 of a 64x64 canvas, so that every moved copy stays on it.
    Scene scene = moved(random_scene(20, 40, 0.5, 6, bits, seed++), {22, 22});
    scene.width = scene.height = 64;
    const std::size_t base = test.cases.size();
    const std::string label = bits == 0 ? "integer triangles" : "1/256 triangles";
    test.cases.push_back(make_case(label, scene, Check::relation));
    for (const glm::ivec2 shift : {glm::ivec2(7, 5), glm::ivec2(-13, 11), glm::ivec2(12, -14)}) {
      test.cases.push_back(make_case(
          label + " moved by (" + std::to_string(shift.x) + ", " + std::to_string(shift.y) + ")",
          moved(scene, glm::dvec2(shift)), Check::relation, Relation{base, shift}));
    }
  }
  return test;
}

// Triangles with vertices out to ±reach that cross a 48x48 canvas: wedges whose long edge runs
// from a half-step point (no centre) in whole-pixel steps out to ±reach, then 1/256 off, so it
// misses centres by less than 1/10000 pixel (rounding decides them wrongly), and slivers between
// far points on opposite sides.
Scene far_scene(double reach, std::uint64_t seed) {
  Random random(seed);
  const auto far_point = [&](glm::dvec2 from, double angle) {
    const glm::dvec2 p = from + reach * glm::dvec2(std::cos(angle), std::sin(angle));
    return on_grid(glm::clamp(p, glm::dvec2(-reach), glm::dvec2(reach)));
  };
  // Whole numbers (x, y) within ±bound drawn until accepted, y after x.
  const auto draw_pair = [&random](int bound, auto accept) {
    for (;;) {
      const int x = random.integer(-bound, bound);
      const int y = random.integer(-bound, bound);
      if (accept(x, y)) return glm::dvec2(x, y);
    }
  };
  // A whole-pixel step with an odd component, so that half of it is no pixel centre.
  const auto step = [&] {
    return draw_pair(7, [](int x, int y) { return x % 2 != 0 || y % 2 != 0; });
  };
  const auto nudge = [&] {
    return unit * draw_pair(3, [](int x, int y) { return x != 0 || y != 0; });
  };
  const auto along = [reach](glm::dvec2 from, glm::dvec2 d) {
    // As many whole steps as stay within ±reach from a start on the canvas.
    return from + std::floor((reach - 64) / std::max(std::abs(d.x), std::abs(d.y))) * d;
  };
  std::vector<Triangle> triangles;
  for (int i = 0; i < 16; ++i) {
    const int x = random.integer(4, 44);
    const int y = random.integer(4, 44);
    const glm::dvec2 first = step();
    const glm::dvec2 second = step();
    const glm::dvec2 first_nudge = nudge();
    const glm::dvec2 second_nudge = nudge();
    const glm::dvec2 centre(x, y);
    const glm::dvec2 near = centre + first / 2.0;
    triangles.push_back(
        Triangle{near, along(centre, first) + first_nudge, along(near, second) + second_nudge});
  }
  for (int i = 0; i < 8; ++i) {
    const double x = random.real(0, 48);
    const double y = random.real(0, 48);
    const double angle = random.real(0, 2 * std::numbers::pi);
    const double offset = random.real(-3, 3);
    const glm::dvec2 through{x, y};
    const glm::dvec2 across(-std::sin(angle), std::cos(angle));
    triangles.push_back(Triangle{far_point(through, angle),
                                 far_point(through, angle + std::numbers::pi),
                                 far_point(through + offset * across, angle + 0.00001)});
  }
  return scene_of(48, 48, triangles);
}

NamedTest range_test(std::string name, double reach, std::string reach_text, std::uint64_t seed) {
  NamedTest test{std::move(name),
                 "triangles with vertices out to " + reach_text +
                     " pixels crossing the canvas, drawn pixel for pixel as the rule says",
                 {}};
  test.cases.push_back(make_case("vertices out to " + reach_text, far_scene(reach, seed)));
  test.cases.push_back(
      make_case("vertices out to " + reach_text + ", second scene", far_scene(reach, seed + 1)));
  return test;
}

NamedTest degenerate_test() {
  NamedTest test{"degenerate",
                 "zero-area triangles (a point, a repeated vertex, collinear vertices) draw "
                 "nothing",
                 {}};
  const auto add = [&](std::string label, Triangle t) {
    test.cases.push_back(make_case(std::move(label), scene_of(32, 32, {t})));
  };
  add("all vertices equal", {{{10, 10}, {10, 10}, {10, 10}}});
  add("two vertices equal", {{{5, 5}, {5, 5}, {25, 17}}});
  add("collinear on a row of centres", {{{2, 8}, {26, 8}, {11, 8}}});
  add("collinear on a column of centres", {{{9, 2}, {9, 27}, {9, 13}}});
  add("collinear on a diagonal of centres", {{{2, 3}, {22, 13}, {12, 8}}});
  add("collinear on the 1/256 grid", {{{2 + 3 * unit, 20 + 5 * unit},
                                       {8 + 3 * unit, 30 + 5 * unit},
                                       {5 + 3 * unit, 25 + 5 * unit}}});
  return test;
}

NamedTest bad_input_test() {
  NamedTest test{"bad_input",
                 "NaN and infinite vertices draw nothing (or the scene is refused with a message) "
                 "and never crash or hang",
                 {}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (auto& hard_case : hard_cases::all_cases()) {
    if (!hard_case.expect_rejection) continue;
    test.cases.push_back(bad_input_case(hard_case.name, std::move(hard_case.scene)));
  }
  // The valid triangle alone, as this rasterizer draws it: beside a bad one it must draw the same.
  const Triangle drawn{{{2, 2}, {12, 3}, {6, 12}}};
  const std::size_t alone = test.cases.size();
  test.cases.push_back(
      make_case("a valid triangle alone", scene_of(32, 32, {drawn}), Check::relation));
  const std::vector<std::pair<std::string, Triangle>> bad{
      {"NaN x, beside a good triangle", {{{16, 16}, {nan, 28}, {28, 18}}}},
      {"NaN y, beside a good triangle", {{{16, 16}, {20, 28}, {28, nan}}}},
      {"minus infinity, beside a good triangle", {{{-inf, 16}, {20, 28}, {28, 18}}}},
      {"all NaN, beside a good triangle", {{{nan, nan}, {nan, nan}, {nan, nan}}}},
  };
  for (const auto& [label, t] : bad) {
    TestCase beside = bad_input_case(label, scene_of(32, 32, {drawn, t}));
    beside.check = Check::relation;
    beside.same_as = Relation{alone, {0, 0}};
    test.cases.push_back(std::move(beside));
  }
  return test;
}

NamedTest determinism_test() {
  NamedTest test{"determinism",
                 "the same scene drawn twice, and with one thread and with all, gives the same "
                 "counts",
                 {}};
  const Scene scene = random_scene(96, 400, 0.5, 40, 8, 2641);
  test.cases.push_back(make_case("first drawing", scene, Check::relation));
  test.cases.push_back(make_case("second drawing", scene, Check::relation, Relation{0, {0, 0}}));
  TestCase one_thread = make_case("one thread", scene, Check::relation, Relation{0, {0, 0}});
  one_thread.threads = Threads::one;
  one_thread.only_threaded = true;
  test.cases.push_back(std::move(one_thread));
  return test;
}

}  // namespace

std::vector<NamedTest> named_tests() {
  std::vector<NamedTest> tests;
  tests.push_back(hard_cases_test());
  tests.push_back(random_triangles_test());
  tests.push_back(watertight_test());
  tests.push_back(tie_rule_test());
  tests.push_back(vertex_order_test());
  tests.push_back(translation_test());
  tests.push_back(range_test("range_32768", 32768, "±32768", 2651));
  tests.push_back(range_test("range_2_30", big, "±2^30", 2661));
  tests.push_back(degenerate_test());
  tests.push_back(bad_input_test());
  tests.push_back(determinism_test());
  return tests;
}

}  // namespace tri::conformance
