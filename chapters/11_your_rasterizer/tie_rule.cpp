#include "chapters/11_your_rasterizer/tie_rule.hpp"

#include <algorithm>
#include <array>
#include <variant>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "common/canvas.hpp"
#include "common/enum_names.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::conformance {
namespace {

constexpr auto tie_rule_names = all_names<TieRule::any>({{TieRule::top_left, "top-left"},
                                                         {TieRule::bottom_left, "bottom-left"},
                                                         {TieRule::any, "any"}});

// Which axes a scene is mirrored in before the oracle draws it: mirroring maps the top-left rule
// onto the bottom-left (y), top-right (x) and bottom-right (both) rules.
struct Mirror {
  bool x = false;
  bool y = false;
};

glm::dvec2 mirrored(glm::dvec2 p, Mirror mirror, int width, int height) {
  // Pixel centres are the integers 0..width-1, so (width - 1) - x maps centres onto centres.
  return {mirror.x ? (width - 1) - p.x : p.x, mirror.y ? (height - 1) - p.y : p.y};
}

std::vector<std::uint32_t> oracle_counts(const Scene& scene, Mirror mirror) {
  Canvas canvas(scene.width, scene.height);
  canvas.enable_write_counts();
  for (const auto& primitive : scene.primitives) {
    const auto* t = std::get_if<SceneTriangle>(&primitive);
    // The original is validated: a mirrored vertex may lie up to a canvas beyond ±2^30, which the
    // oracle still decides exactly.
    if (t == nullptr || validate_triangle(t->vertices) != DrawResult::drawn) continue;
    Triangle triangle;
    for (int i = 0; i < 3; ++i) {
      triangle[static_cast<std::size_t>(i)] =
          mirrored(t->vertices[static_cast<std::size_t>(i)], mirror, scene.width, scene.height);
    }
    ch07::draw_triangle_oracle(canvas, triangle, t->color);
  }
  // Read back through the same mirror, so that pixel (x, y) holds the count of the scene's (x, y).
  std::vector<std::uint32_t> counts(canvas.write_counts().size());
  for (int y = 0; y < scene.height; ++y) {
    for (int x = 0; x < scene.width; ++x) {
      const int mx = mirror.x ? scene.width - 1 - x : x;
      const int my = mirror.y ? scene.height - 1 - y : y;
      counts[pixel_index(x, y, scene.width)] = canvas.write_count(mx, my);
    }
  }
  return counts;
}

}  // namespace

std::string_view tie_rule_name(TieRule rule) noexcept {
  return name_in(tie_rule_names, rule, "?");
}

std::optional<TieRule> parse_tie_rule(std::string_view name) noexcept {
  return value_named(tie_rule_names, name);
}

TieRule declared_tie_rule(CoverageRule rule) noexcept {
  // Every rule named, so that a newly declared exact rule cannot be missed here (-Wswitch).
  switch (rule) {
    case CoverageRule::top_left:
      return TieRule::top_left;
    case CoverageRule::bottom_left:
      return TieRule::bottom_left;
    case CoverageRule::inclusive:  // every tie covered: no consistent rule, graded by the truth
    case CoverageRule::approximate:
    case CoverageRule::area:
      return TieRule::top_left;
  }
  return TieRule::top_left;
}

ExpectedCounts expected_counts(const Scene& scene, TieRule rule) {
  if (rule == TieRule::top_left) {
    auto counts = oracle_counts(scene, {});
    return {counts, counts};
  }
  if (rule == TieRule::bottom_left) {
    auto counts = oracle_counts(scene, {.x = false, .y = true});
    return {counts, counts};
  }
  ExpectedCounts range{oracle_counts(scene, {}), oracle_counts(scene, {})};
  for (const Mirror mirror : {Mirror{true, false}, Mirror{false, true}, Mirror{true, true}}) {
    const auto counts = oracle_counts(scene, mirror);
    for (std::size_t i = 0; i < counts.size(); ++i) {
      range.low[i] = std::min(range.low[i], counts[i]);
      range.high[i] = std::max(range.high[i], counts[i]);
    }
  }
  return range;
}

}  // namespace tri::conformance
