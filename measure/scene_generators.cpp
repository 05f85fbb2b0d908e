#include "measure/scene_generators.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "chapters/07_exact_coverage/jittered_mesh.hpp"
#include "common/random.hpp"

namespace tri {
namespace {

glm::dvec2 snapped(glm::dvec2 p, int bits) {
  return {snap_to_grid(p.x, bits), snap_to_grid(p.y, bits)};
}

void add(Scene& scene, Random& random, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, int bits) {
  scene.primitives.emplace_back(
      SceneTriangle{{snapped(a, bits), snapped(b, bits), snapped(c, bits)}, random_color(random)});
}

// A point drawn uniformly from the box [low, high]: y is drawn before x, the order the scenes
// were first generated in. Each draw is its own statement, since a call's arguments are evaluated
// in an order the language leaves open (and GCC and Clang choose differently).
glm::dvec2 random_point(Random& random, glm::dvec2 low, glm::dvec2 high) {
  const double y = random.real(low.y, high.y);
  const double x = random.real(low.x, high.x);
  return {x, y};
}

// A point drawn uniformly from the square [low, high]^2, y before x.
glm::dvec2 random_point(Random& random, double low, double high) {
  return random_point(random, {low, low}, {high, high});
}

double area_of(const SceneTriangle& t) {
  const auto& [a, b, c] = t.vertices;
  return std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
}

void random_triangles(const SceneRecipe& r, Scene& scene, Random& random) {
  for (int i = 0; i < r.triangles;) {
    const double extent = random.real(r.min_extent, r.max_extent);
    const glm::dvec2 centre = random_point(random, {0, 0}, {r.width, r.height});
    const auto vertex = [&] { return centre + random_point(random, -extent, extent); };
    // The third vertex is drawn first, as the scenes were first generated.
    const glm::dvec2 c = vertex();
    const glm::dvec2 b = vertex();
    const glm::dvec2 a = vertex();
    add(scene, random, a, b, c, r.grid_bits);
    const double area = area_of(std::get<SceneTriangle>(scene.primitives.back()));
    if (area < r.min_area || area > r.max_area) {
      scene.primitives.pop_back();  // outside the asked areas: drawn again
    } else {
      ++i;
    }
  }
}

void slivers(const SceneRecipe& r, Scene& scene, Random& random) {
  for (int i = 0; i < r.triangles; ++i) {
    const double length = random.real(r.min_extent, r.max_extent);
    const double angle = random.real(0, 2 * std::numbers::pi);
    const glm::dvec2 a = random_point(random, {0, 0}, {r.width, r.height});
    const glm::dvec2 direction(std::cos(angle), std::sin(angle));
    const glm::dvec2 b = a + length * direction;
    // The third vertex sits less than half a pixel off the long edge.
    const glm::dvec2 normal(-direction.y, direction.x);
    // The offset across is drawn before the position along, as the scenes were first generated.
    const double across = random.real(-0.5, 0.5);
    const double along = random.real(0.2, 0.8);
    const glm::dvec2 c = a + along * length * direction + across * normal;
    add(scene, random, a, b, c, r.grid_bits);
  }
}

void fan(const SceneRecipe& r, Scene& scene, Random& random) {
  const glm::dvec2 centre = glm::dvec2(r.width, r.height) / 2.0 + random_point(random, -0.5, 0.5);
  const double radius = 0.45 * std::min(r.width, r.height);
  // Rim points are snapped once and shared by both neighbours, so the edges match exactly.
  std::vector<glm::dvec2> rim;
  for (int i = 0; i < r.triangles; ++i) {
    const double angle = 2 * std::numbers::pi * i / r.triangles;
    rim.push_back(
        snapped(centre + radius * glm::dvec2(std::cos(angle), std::sin(angle)), r.grid_bits));
  }
  for (int i = 0; i < r.triangles; ++i) {
    add(scene, random, centre, rim[i], rim[(i + 1) % r.triangles], r.grid_bits);
  }
}

void jittered_grid(const SceneRecipe& r, Scene& scene, Random& random) {
  // Cells as square as possible, two triangles each, covering the canvas with a margin.
  const int cells = std::max(1, r.triangles / 2);
  const double aspect = static_cast<double>(r.width) / r.height;
  const int nx = std::max(1, static_cast<int>(std::lround(std::sqrt(cells * aspect))));
  const int ny = std::max(1, (cells + nx - 1) / nx);  // round up: at least the triangles asked for
  // Chapter 07's mesh, its border vertices sliding along the border and its diagonals
  // alternating, so the mesh has edges of every direction.
  const ch07::JitteredGrid grid{.columns = nx,
                                .rows = ny,
                                .origin = {-1, -1},
                                .cell = {(r.width + 2.0) / nx, (r.height + 2.0) / ny},
                                .jitter = 0.15,
                                .grid_bits = r.grid_bits,
                                .pin_border_vertices = false,
                                .alternate_diagonals = true};
  for (const Triangle& t : ch07::jittered_grid_triangles(grid, random)) {
    scene.primitives.emplace_back(SceneTriangle{t, random_color(random)});
  }
}

// Blend2D's bl_bench FillTriangle shape: the square's corner uniform over the canvas less its
// side, then each vertex uniform inside the square, x before y.
void in_boxes(const SceneRecipe& r, Scene& scene, Random& random) {
  // [listing in_boxes]
  const double side = r.box_side;
  for (int i = 0; i < r.triangles; ++i) {
    const double corner_x = random.real(0, r.width - side);
    const double corner_y = random.real(0, r.height - side);
    glm::dvec2 vertices[3];
    for (glm::dvec2& v : vertices) {
      v.x = random.real(corner_x, corner_x + side);
      v.y = random.real(corner_y, corner_y + side);
    }
    add(scene, random, vertices[0], vertices[1], vertices[2], r.grid_bits);
  }
  // [/listing]
}

}  // namespace

Color random_color(Random& random) {
  return Color{static_cast<std::uint8_t>(random.integer(64, 255)),
               static_cast<std::uint8_t>(random.integer(64, 255)),
               static_cast<std::uint8_t>(random.integer(64, 255)), 255};
}

double snap_to_grid(double value, int bits) noexcept {
  const double scale = std::ldexp(1.0, bits);
  return std::floor(value * scale + 0.5) / scale;
}

bool is_mesh(const SceneRecipe& recipe) noexcept {
  return recipe.kind == SceneRecipe::Kind::fan || recipe.kind == SceneRecipe::Kind::jittered_grid;
}

Scene generate_scene(const SceneRecipe& recipe) {
  Scene scene;
  scene.width = recipe.width;
  scene.height = recipe.height;
  Random random(recipe.seed);
  switch (recipe.kind) {
    case SceneRecipe::Kind::random:
      random_triangles(recipe, scene, random);
      break;
    case SceneRecipe::Kind::slivers:
      slivers(recipe, scene, random);
      break;
    case SceneRecipe::Kind::fan:
      fan(recipe, scene, random);
      break;
    case SceneRecipe::Kind::jittered_grid:
      jittered_grid(recipe, scene, random);
      break;
    case SceneRecipe::Kind::in_boxes:
      in_boxes(recipe, scene, random);
      break;
  }
  return scene;
}

}  // namespace tri
