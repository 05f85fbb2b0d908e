#include "chapters/11_your_rasterizer/failure_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <glm/common.hpp>

#include "common/canvas.hpp"
#include "common/pixel_diagram.hpp"

namespace tri::conformance {
namespace {

namespace colors = diagram_colors;

struct View {
  glm::ivec2 first, last;
};

bool finite(glm::dvec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

// The case's triangles with a margin of one pixel when they fit in max_diagram_side, else the
// wrong pixels with a margin of two, cut to the canvas and to max_diagram_side around the first.
View view_of(const WrongCase& wrong) {
  std::vector<glm::ivec2> all = wrong.missed;
  all.insert(all.end(), wrong.extra.begin(), wrong.extra.end());
  const glm::ivec2 canvas_last(wrong.scene.width - 1, wrong.scene.height - 1);
  if (all.empty()) return {{0, 0}, glm::min(canvas_last, glm::ivec2(max_diagram_side - 1))};
  glm::ivec2 low = all.front(), high = all.front();
  for (const glm::ivec2 p : all) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  glm::dvec2 scene_low(wrong.scene.width, wrong.scene.height), scene_high(-1, -1);
  for (const auto& primitive : wrong.scene.primitives) {
    const auto* t = std::get_if<SceneTriangle>(&primitive);
    if (t == nullptr || !std::all_of(t->vertices.begin(), t->vertices.end(), finite)) continue;
    for (const glm::dvec2 v : t->vertices) {
      scene_low = glm::min(scene_low, v);
      scene_high = glm::max(scene_high, v);
    }
  }
  const glm::ivec2 whole_low =
      glm::max(glm::ivec2(glm::floor(glm::max(scene_low, -1.0))) - 1, glm::ivec2(0));
  const glm::ivec2 whole_high = glm::min(
      glm::ivec2(glm::ceil(glm::min(scene_high, glm::dvec2(canvas_last) + 1.0))) + 1, canvas_last);
  const glm::ivec2 with_scene_low = glm::min(low, whole_low),
                   with_scene_high = glm::max(high, whole_high);
  const glm::ivec2 size = with_scene_high - with_scene_low + 1;
  if (size.x <= max_diagram_side && size.y <= max_diagram_side) {
    return {with_scene_low, with_scene_high};
  }
  low = glm::max(low - 2, glm::ivec2(0));
  high = glm::min(high + 2, canvas_last);
  high = glm::min(high, low + (max_diagram_side - 1));
  return {low, high};
}

}  // namespace

std::string failure_diagram_svg(const WrongCase& wrong, const std::string& title) {
  const View view = view_of(wrong);
  const int extent = std::max(view.last.x - view.first.x, view.last.y - view.first.y) + 1;
  const double cell = std::clamp(std::floor(400.0 / extent), 10.0, 40.0);
  PixelDiagram diagram(view.first, view.last, title, cell);
  for (int y = view.first.y; y <= view.last.y; ++y) {
    for (int x = view.first.x; x <= view.last.x; ++x) {
      if (wrong.expected[pixel_index(x, y, wrong.scene.width)] > 0) {
        diagram.fill({x, y}, colors::covered);
      }
    }
  }
  for (const auto& primitive : wrong.scene.primitives) {
    const auto* t = std::get_if<SceneTriangle>(&primitive);
    if (t == nullptr || !std::all_of(t->vertices.begin(), t->vertices.end(), finite)) continue;
    diagram.triangle(t->vertices[0], t->vertices[1], t->vertices[2], colors::blue, 1.5);
  }
  for (const glm::ivec2 p : wrong.missed) diagram.mark(p, PixelMark::cross, colors::vermillion);
  for (const glm::ivec2 p : wrong.extra) diagram.mark(p, PixelMark::cross, colors::purple);
  for (const glm::ivec2 p : wrong.doubled) diagram.mark(p, PixelMark::hatch, colors::orange);
  diagram.legend_fill("expected", colors::covered);
  diagram.legend_line("triangle edge", colors::blue);
  diagram.legend_mark("missed (" + std::to_string(wrong.missed.size()) + ")", PixelMark::cross,
                      colors::vermillion);
  diagram.legend_mark("extra (" + std::to_string(wrong.extra.size()) + ")", PixelMark::cross,
                      colors::purple);
  diagram.legend_mark("written twice or more (" + std::to_string(wrong.doubled.size()) + ")",
                      PixelMark::hatch, colors::orange);
  return diagram.svg();
}

}  // namespace tri::conformance
