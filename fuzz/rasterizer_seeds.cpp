#include "fuzz/rasterizer_seeds.hpp"

#include <limits>

#include "fuzz/rasterizer_input.hpp"

namespace tri::fuzz {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double limit = max_scene_coordinate;

// An interesting coordinate: base + whole + fraction / 256.
constexpr InterestingValue v(Base base, int whole = 0, int fraction = 0) {
  return {base, static_cast<std::int8_t>(whole), static_cast<std::uint8_t>(fraction)};
}
// A small coordinate on the 1/256 grid: whole + fraction / 256 (whole in -128..127).
constexpr InterestingValue g(int whole, int fraction = 0) {
  return v(Base::zero, whole, fraction);
}

// The selector only matters to the fuzzer (the regression test replays every seed with every
// algorithm); spreading it makes the first executions visit different algorithms.
NamedSeed raw(std::string name, std::uint8_t selector, int size, const Triangle& t,
              Color color = colors::white) {
  return {std::move(name), RasterizerInputWriter(selector, size, size).raw(t, color).bytes()};
}

NamedSeed interesting(std::string name, std::uint8_t selector, int size,
                      const std::array<InterestingValue, 6>& c, Color color = colors::white) {
  return {std::move(name),
          RasterizerInputWriter(selector, size, size).interesting(c, color).bytes()};
}

}  // namespace

std::vector<NamedSeed> rasterizer_seeds() {
  std::vector<NamedSeed> seeds{
      raw("raw_small_triangle", 0, 32, {{{3, 4}, {28, 9}, {12, 27}}}),
      raw("raw_tinyrenderer_shape", 1, 64, {{{10, 7}, {50, 16}, {7, 8}}}, colors::red),
      raw("raw_all_vertices_equal", 2, 16, {{{5, 5}, {5, 5}, {5, 5}}}),
      raw("raw_two_vertices_equal", 3, 16, {{{2, 2}, {2, 2}, {13, 9}}}),
      raw("raw_collinear_horizontal", 4, 16, {{{1, 6}, {14, 6}, {7, 6}}}),
      raw("raw_collinear_vertical", 5, 16, {{{6, 1}, {6, 14}, {6, 8}}}),
      raw("raw_collinear_diagonal", 6, 16, {{{1, 2}, {13, 8}, {7, 5}}}),
      raw("raw_horizontal_top_edge", 7, 16, {{{2, 12}, {14, 12}, {7, 2}}}),
      raw("raw_horizontal_bottom_edge", 8, 16, {{{2, 3}, {14, 3}, {9, 13}}}),
      raw("raw_needle_below_a_pixel_high", 9, 32, {{{1, 5.25}, {30, 5.5}, {16, 5.75}}}),
      raw("raw_subpixel_covering_one_centre", 10, 8, {{{3.75, 3.75}, {4.5, 3.9}, {4.1, 4.6}}}),
      raw("raw_subpixel_covering_no_centre", 11, 8, {{{3.1, 3.1}, {3.6, 3.2}, {3.3, 3.7}}}),
      raw("raw_clockwise", 12, 32, {{{3, 4}, {12, 27}, {28, 9}}}),
      raw("raw_far_vertices_1e7", 13, 16, {{{-1e7, -1e7}, {1e7, 3}, {4, 1e7}}}),
      raw("raw_covering_whole_canvas", 14, 64, {{{-limit, -limit}, {limit, -limit}, {0, limit}}}),
      raw("raw_beyond_float_integers", 15, 16,
          {{{16777217, 16777217}, {-16777217, 5}, {5, -16777217}}}),
      raw("raw_nan_vertex", 16, 16, {{{nan, 3}, {10, 3}, {5, 12}}}),
      raw("raw_infinite_vertex", 17, 16, {{{2, 3}, {inf, 3}, {5, -inf}}}),
      raw("raw_beyond_limit", 18, 16, {{{2, 3}, {10, 3}, {5, limit + 1.0 / 256}}}),
      raw("raw_largest_double", 19, 16,
          {{{2, 3}, {std::numeric_limits<double>::max(), 3}, {5, 12}}}),
      raw("raw_subnormal_coordinates", 20, 4, {{{1e-310, 0}, {3, 1e-310}, {0, 3}}}),
      raw("raw_almost_half", 21, 4,
          {{{0.49999999999999994, 0.49999999999999994}, {3.5, 0.5}, {0.5, 3.5}}}),
      raw("raw_one_by_one_canvas", 22, 1, {{{-1, -1}, {2, -1}, {0, 2}}}),
      interesting("grid_edges_through_centres", 23, 16, {g(0), g(0), g(8), g(0), g(0), g(8)}),
      interesting("grid_shared_vertex_ties", 24, 16, {g(4), g(4), g(12), g(4), g(4), g(12)}),
      interesting("grid_quarter_pixel_offsets", 25, 16,
                  {g(1, 64), g(2, 192), g(14, 128), g(3), g(6, 32), g(13, 224)}),
      interesting("grid_negative_fractions", 26, 16,
                  {g(-3, 128), g(-2), g(15, 1), g(4, 255), g(2), g(18, 128)}),
      interesting("interesting_limits", 27, 32,
                  {v(Base::minus_limit), v(Base::minus_limit), v(Base::limit), v(Base::zero, 5),
                   v(Base::zero, 9), v(Base::limit)}),
      interesting("interesting_half_limit", 28, 32,
                  {v(Base::minus_half_limit, 0, 1), v(Base::zero, 3), v(Base::half_limit),
                   v(Base::zero, 20), v(Base::zero, 7), v(Base::half_limit, -1, 255)}),
      interesting("interesting_ten_million", 29, 24,
                  {v(Base::ten_million), v(Base::zero, 2), v(Base::zero, 1),
                   v(Base::minus_ten_million), v(Base::zero, 20, 128), v(Base::zero, 20, 128)}),
      interesting("interesting_float_gap", 30, 24,
                  {v(Base::float_gap), v(Base::float_gap), v(Base::minus_float_gap),
                   v(Base::zero, 12), v(Base::zero, 10), v(Base::minus_float_gap)}),
      interesting("interesting_beyond_int", 31, 24,
                  {v(Base::beyond_int), v(Base::zero), v(Base::zero), v(Base::beyond_int),
                   v(Base::zero, 3), v(Base::zero, 3)}),
      interesting("interesting_nan_and_infinities", 32, 8,
                  {v(Base::not_a_number), v(Base::infinity), v(Base::minus_infinity), v(Base::zero),
                   v(Base::zero, 4), v(Base::zero, 4)}),
      interesting("interesting_canvas_edge", 33, 64,
                  {v(Base::canvas_edge), v(Base::canvas_edge, -1, 128), v(Base::zero, -1),
                   v(Base::canvas_edge), v(Base::canvas_edge, -1), v(Base::zero, -1, 128)}),
      interesting("interesting_minus_zero", 34, 8,
                  {v(Base::minus_zero), v(Base::minus_zero), v(Base::zero, 6), v(Base::minus_zero),
                   v(Base::minus_zero), v(Base::zero, 6)}),
  };
  // Four triangles at once: a fan with shared edges (order and the batch entry point matter).
  RasterizerInputWriter fan(35, 32, 32);
  fan.interesting({g(16), g(16), g(30), g(16), g(16), g(30)}, colors::red)
      .interesting({g(16), g(16), g(16), g(30), g(2), g(16)}, colors::green)
      .interesting({g(16), g(16), g(2), g(16), g(16), g(2)}, colors::blue)
      .interesting({g(16), g(16), g(16), g(2), g(30), g(16)}, colors::yellow);
  seeds.push_back({"batch_fan_of_four", fan.bytes()});
  // A refused triangle between two drawn ones: the batch must skip it and keep the order.
  RasterizerInputWriter mixed(36, 16, 16);
  mixed.raw({{{1, 1}, {14, 2}, {6, 13}}}, colors::cyan)
      .raw({{{nan, nan}, {3, 3}, {9, 4}}}, colors::magenta)
      .raw({{{2, 12}, {13, 14}, {12, 1}}}, colors::yellow);
  seeds.push_back({"batch_refused_in_the_middle", mixed.bytes()});
  return seeds;
}

}  // namespace tri::fuzz
