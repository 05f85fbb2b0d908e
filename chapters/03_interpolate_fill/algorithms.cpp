#include "chapters/03_interpolate_fill/algorithms.hpp"

#include <array>

#include "chapters/03_interpolate_fill/filled_triangle.hpp"

namespace tri::ch03 {
namespace {

// [listing registered]
// Approximate, not inclusive: span ends round to the nearest column, so centres up to half a
// pixel outside an edge are drawn too (see the chapter's README for the measured count).
constexpr std::array<TriangleAlgorithm, 1> algorithms{{
    {.name = "gambetta_interpolate_fill",
     .chapter = "03_interpolate_fill",
     .rule = CoverageRule::approximate,
     .summary =
         "Gambetta's Listing 7-1: x = f(y) per edge by Interpolate, spans rounded to nearest",
     .draw = draw_at_nearest_pixels<draw_filled_triangle>},
}};
// [/listing]

}  // namespace

std::span<const TriangleAlgorithm> triangle_algorithms() {
  return algorithms;
}

}  // namespace tri::ch03
