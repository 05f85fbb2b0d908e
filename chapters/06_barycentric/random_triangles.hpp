/// @file
/// Seeded triangles with an edge through a pixel centre for chapter 06's tests, and the fill they
/// test (tests only). Random points and triangles in a range are tri::testing's.
#pragma once

#include "chapters/06_barycentric/examples.hpp"
#include "chapters/06_barycentric/fill.hpp"
#include "tests/support/pixels.hpp"

namespace tri::ch06::testing {

/// Two vertices within ±reach and the third placed so that a random pixel centre of a size x size
/// canvas is the midpoint of an edge: the edge crosses the canvas through a pixel centre, where
/// rounding decides. Precondition: reach + 2 * size <= 2^30.
inline PixelTriangle triangle_with_edge_through_canvas(tri::testing::Random& random, int reach,
                                                       int size) {
  using tri::testing::random_point;
  const glm::ivec2 a = random_point(random, -reach, reach);
  const glm::ivec2 b = random_point(random, -reach, reach);
  const glm::ivec2 m = random_point(random, 0, size - 1);
  return {a, b, 2 * m - b};
}

/// A width x height canvas with write counts, after the guarded barycentric fill of t.
template <typename Scalar>
Canvas filled(const PixelTriangle& t, int width, int height) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  fill_triangle_barycentric<Scalar>(canvas, t[0], t[1], t[2], tri::colors::white);
  return canvas;
}

/// The pixels the guarded barycentric fill of t writes on a width x height canvas.
template <typename Scalar>
tri::testing::PixelSet filled_pixels(const PixelTriangle& t, int width, int height) {
  return tri::testing::written_pixels(filled<Scalar>(t, width, height));
}

}  // namespace tri::ch06::testing
