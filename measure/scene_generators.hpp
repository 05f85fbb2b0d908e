/// @file
/// Seeded scene families shared by the tests and the speed-vs-error report: random triangles of
/// chosen sizes, slivers, fans, jittered-grid meshes and Blend2D's benchmark triangles, on the
/// integer or the 1/256 grid.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "common/random.hpp"
#include "common/scene.hpp"

namespace tri {

/// What a generated scene looks like.
struct SceneRecipe {
  enum class Kind {
    random,         ///< independent triangles of a chosen extent (overlaps allowed)
    slivers,        ///< long needles less than a pixel thick
    fan,            ///< triangles around one centre, sharing edges
    jittered_grid,  ///< a grid of cells split in two, vertices jittered: a mesh
    in_boxes,  ///< three points in a box_side square placed anywhere on the canvas (bl_bench's)
  };
  Kind kind = Kind::random;
  int width = 256;
  int height = 256;
  int triangles = 1000;      ///< how many (a mesh or fan may round to its shape)
  double min_extent = 1.0;   ///< random: vertices within ±extent of a centre, extent drawn from
  double max_extent = 10.0;  ///< [min_extent, max_extent]
  double min_area = 0;       ///< random: a triangle whose area is outside [min_area, max_area]
  double max_area = std::numeric_limits<double>::infinity();  ///< is drawn again
  double box_side = 8;  ///< in_boxes: the side of each triangle's square
  int grid_bits = 8;    ///< vertices rounded to 1/2^grid_bits (0: integer pixel centres)
  std::uint64_t seed = 1;
};

/// Builds the scene a recipe describes, deterministically.
Scene generate_scene(const SceneRecipe& recipe);

/// True when the scene's triangles tile a region without overlap (fan, jittered grid), so gaps
/// and overdraw are meaningful.
bool is_mesh(const SceneRecipe& recipe) noexcept;

/// A random opaque colour, each channel in [64, 255] so it stands out on black: the colour of
/// every generated triangle.
Color random_color(Random& random);

/// Rounds a coordinate to the 1/2^bits grid.
double snap_to_grid(double value, int bits) noexcept;

}  // namespace tri
