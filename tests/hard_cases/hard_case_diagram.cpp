#include "tests/hard_cases/hard_case_diagram.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <variant>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "chapters/07_exact_coverage/exact_orientation.hpp"
#include "common/pixel_diagram.hpp"

namespace tri::hard_cases {
namespace {

namespace colors = diagram_colors;

std::vector<Triangle> triangles_of(const HardCase& hard_case) {
  std::vector<Triangle> triangles;
  for (const auto& primitive : hard_case.scene.primitives) {
    if (const auto* t = std::get_if<SceneTriangle>(&primitive)) triangles.push_back(t->vertices);
  }
  return triangles;
}

bool finite(glm::dvec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

std::string number(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

// Whether the pixel centre p lies exactly on the closed segment a-b (exact arithmetic).
bool on_segment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  if (ch07::exact_orientation(a, b, p) != 0) return false;
  return p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x) && p.y >= std::min(a.y, b.y) &&
         p.y <= std::max(a.y, b.y);
}

struct View {
  glm::ivec2 first, last;
};

View view_of(const HardCase& hard_case) {
  const int w = hard_case.scene.width, h = hard_case.scene.height;
  if (reaches_beyond_canvas(hard_case)) return {{0, 0}, {w - 1, h - 1}};
  glm::dvec2 low(w, h), high(-1, -1);
  for (const auto& t : triangles_of(hard_case)) {
    for (const auto& v : t) {
      low = glm::min(low, v);
      high = glm::max(high, v);
    }
  }
  // One pixel of margin around the triangles, inside the canvas.
  return {{std::max(0, static_cast<int>(std::floor(low.x)) - 1),
           std::max(0, static_cast<int>(std::floor(low.y)) - 1)},
          {std::min(w - 1, static_cast<int>(std::ceil(high.x)) + 1),
           std::min(h - 1, static_cast<int>(std::ceil(high.y)) + 1)}};
}

// Labels point away from the middle of the view, so they stay inside the picture.
LabelPlace place_for(glm::dvec2 p, const View& view) {
  const glm::dvec2 middle = glm::dvec2(view.first + view.last) / 2.0;
  if (p.y <= middle.y) return p.x <= middle.x ? LabelPlace::below_right : LabelPlace::below_left;
  return p.x <= middle.x ? LabelPlace::above_right : LabelPlace::above_left;
}

}  // namespace

std::string coordinates(glm::dvec2 p) {
  return "(" + number(p.x) + ", " + number(p.y) + ")";
}

std::vector<NamedVertex> named_vertices(const HardCase& hard_case) {
  const auto triangles = triangles_of(hard_case);
  if (triangles.size() > 2) return {};
  std::vector<NamedVertex> named;
  char letter = 'A';
  for (const auto& t : triangles) {
    for (const auto& v : t) {
      const std::string name(1, letter++);
      const auto same = std::find_if(named.begin(), named.end(), [&](const NamedVertex& n) {
        return n.position.x == v.x && n.position.y == v.y;
      });
      if (same != named.end()) {
        same->name += " = " + name;
      } else {
        named.push_back({name, v});
      }
    }
  }
  return named;
}

bool reaches_beyond_canvas(const HardCase& hard_case) {
  const double w = hard_case.scene.width, h = hard_case.scene.height;
  for (const auto& t : triangles_of(hard_case)) {
    for (const auto& v : t) {
      if (!finite(v) || v.x < -0.5 || v.y < -0.5 || v.x > w - 0.5 || v.y > h - 0.5) return true;
    }
  }
  return false;
}

std::string diagram_name(const HardCase& hard_case) {
  return "hard_case_" + hard_case.name;
}

std::string diagram_svg(const HardCase& hard_case) {
  const View view = view_of(hard_case);
  const int extent = std::max(view.last.x - view.first.x, view.last.y - view.first.y) + 1;
  const double cell = std::clamp(std::floor(320.0 / extent), 10.0, 48.0);
  PixelDiagram diagram(view.first, view.last, hard_case.name, cell);
  const auto triangles = triangles_of(hard_case);

  // The truth: the pixels the exact oracle covers, and the centres exactly on an edge (where the
  // top-left rule decides).
  bool any_covered = false, any_tie = false;
  for (int y = view.first.y; y <= view.last.y; ++y) {
    for (int x = view.first.x; x <= view.last.x; ++x) {
      const glm::ivec2 pixel(x, y);
      bool covered = false, tie = false;
      for (const auto& t : triangles) {
        if (!std::all_of(t.begin(), t.end(), finite)) continue;
        covered = covered || ch07::oracle_covers(t, pixel);
        for (int i = 0; i < 3; ++i) tie = tie || on_segment(t[i], t[(i + 1) % 3], pixel);
      }
      if (covered) diagram.fill(pixel, colors::covered);
      if (tie) diagram.mark(pixel, PixelMark::ring, colors::vermillion);
      any_covered = any_covered || covered;
      any_tie = any_tie || tie;
    }
  }

  // The ideal edges, cut to the picture (a vertex may lie 2^30 pixels away).
  const glm::dvec2 low = glm::dvec2(view.first) - 0.5, high = glm::dvec2(view.last) + 0.5;
  const double width = triangles.size() > 2 ? 1.5 : 2;
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) {
      const glm::dvec2 a = t[i], b = t[(i + 1) % 3];
      if (!finite(a) || !finite(b)) continue;
      if (const auto part = tri::clip_segment(a, b, low, high)) {
        diagram.line((*part)[0], (*part)[1], colors::blue, width);
      }
    }
  }

  // The vertices: labelled with their coordinates where there is room, listed under the picture
  // when they lie outside it.
  const auto named = named_vertices(hard_case);
  double smallest_gap = 1e300;
  for (std::size_t i = 0; i < named.size(); ++i) {
    for (std::size_t j = i + 1; j < named.size(); ++j) {
      smallest_gap = std::min(smallest_gap, glm::length(named[i].position - named[j].position));
    }
  }
  // Coordinates where the labels have room, letters where they are close, nothing where the
  // vertices almost coincide (a triangle much smaller than a pixel): the page lists them.
  const bool room_for_coordinates = smallest_gap * cell >= 60;
  const bool room_for_letters = smallest_gap * cell >= 16;
  std::vector<std::string> outside, not_finite;
  for (const auto& [name, p] : named) {
    if (!finite(p)) {
      not_finite.push_back(name + " " + coordinates(p));
    } else if (!room_for_letters) {
      continue;
    } else if (p.x >= low.x && p.x <= high.x && p.y >= low.y && p.y <= high.y) {
      diagram.point(p, colors::black, 3.5);
      diagram.label(p, room_for_coordinates ? name + " " + coordinates(p) : name,
                    place_for(p, view));
    } else {
      outside.push_back(name + " " + coordinates(p));
    }
  }
  const auto listed = [](std::string heading, const std::vector<std::string>& items) {
    for (std::size_t i = 0; i < items.size(); ++i) heading += (i ? ", " : " ") + items[i];
    return heading;
  };

  diagram.legend_fill("covered by the exact oracle", colors::covered);
  diagram.legend_line("triangle edge", colors::blue);
  if (any_tie)
    diagram.legend_mark("centre exactly on an edge", PixelMark::ring, colors::vermillion);
  if (!any_covered) diagram.legend_note("No pixel centre is covered: nothing may be drawn.");
  if (!outside.empty()) diagram.legend_note(listed("Outside the picture:", outside));
  if (!not_finite.empty()) {
    diagram.legend_note(listed("Not finite, so not drawn (nor their edges):", not_finite));
  }
  if (!named.empty() && !room_for_coordinates) {
    diagram.legend_note("Vertex coordinates: under the picture on the page.");
  }
  return diagram.svg();
}

}  // namespace tri::hard_cases
