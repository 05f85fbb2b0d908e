/// @file
/// Helpers the tests share: pixel sets read back from a canvas and their algebra, the six orders
/// of a triangle's vertices, and a portable random generator with the points and triangles it
/// draws.
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <utility>

#include <glm/vec2.hpp>

#include "common/canvas.hpp"
#include "common/random.hpp"

namespace tri::testing {

/// A set of pixels as (x, y) pairs; ordered, so Catch prints it readably and sets compare.
using PixelSet = std::set<std::pair<int, int>>;

/// Every pixel written at least once (the canvas must count writes).
PixelSet written_pixels(const Canvas& canvas);

/// Pixels written more than once (the canvas must count writes).
PixelSet overdrawn_pixels(const Canvas& canvas);

/// The pixels `draw(canvas)` writes on a fresh width x height canvas that counts writes.
template <typename Draw>
PixelSet pixels_drawn(int width, int height, Draw&& draw) {
  Canvas canvas(width, height);
  canvas.enable_write_counts();
  draw(canvas);
  return written_pixels(canvas);
}

/// The pixels of `from` that are not in `without`.
PixelSet minus(const PixelSet& from, const PixelSet& without);
/// The pixels in both sets.
PixelSet intersection(const PixelSet& a, const PixelSet& b);
/// The pixels in either set.
PixelSet united(const PixelSet& a, const PixelSet& b);
/// The pixels in exactly one of the two sets.
PixelSet symmetric_difference(const PixelSet& a, const PixelSet& b);

/// A triangle's three integer vertices.
using VertexTriple = std::array<glm::ivec2, 3>;

/// The six orders in which the three vertices of a triangle can be passed (both windings), for
/// whole-pixel or double vertices alike.
template <class Vertex>
std::array<std::array<Vertex, 3>, 6> vertex_orders(const std::array<Vertex, 3>& t) {
  return {{{t[0], t[1], t[2]},
           {t[0], t[2], t[1]},
           {t[1], t[0], t[2]},
           {t[1], t[2], t[0]},
           {t[2], t[0], t[1]},
           {t[2], t[1], t[0]}}};
}
/// The same for three whole-pixel vertices given one by one.
std::array<VertexTriple, 6> vertex_orders(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c);

/// Twice the signed area of the triangle abc in exact 64-bit arithmetic: > 0 counter-clockwise
/// (y up), 0 for collinear vertices.
std::int64_t doubled_area(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c);

/// The pixel centres inside or on the edges of the triangle abc (integer vertices, either
/// winding), clipped to a width x height canvas: exact, brute force, with 64-bit cross products.
/// What an `inclusive` algorithm must draw for a triangle of non-zero area; empty for zero area.
PixelSet inclusive_pixels(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, int width, int height);

/// The portable seeded generator, under the name the tests use.
using Random = tri::Random;

/// A point with both coordinates in [low, high], x drawn first.
glm::ivec2 random_point(Random& random, int low, int high);

/// Three points with coordinates in [low, high], drawn one after the other by random_point.
VertexTriple random_vertices(Random& random, int low, int high);

/// A point with both coordinates real numbers in [low, high), x drawn first.
glm::dvec2 random_real_point(Random& random, double low, double high);

/// Three points drawn one after the other by random_real_point: a triangle of doubles.
std::array<glm::dvec2, 3> random_real_triangle(Random& random, double low, double high);

}  // namespace tri::testing
