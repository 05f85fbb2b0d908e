#include "measure/area_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/coverage_error.hpp"

namespace tri {
namespace {

/// The pixels a triangle can reach (its bounding box and one pixel around it) on the canvas.
AreaTruth::TriangleTruth region_of(const Triangle& t, int width, int height) {
  const auto [low_x, high_x] = std::minmax({t[0].x, t[1].x, t[2].x});
  const auto [low_y, high_y] = std::minmax({t[0].y, t[1].y, t[2].y});
  const auto pixel = [](double v) { return static_cast<int>(std::floor(v + 0.5)); };
  return {std::max(0, pixel(low_x) - 1),
          std::min(width - 1, pixel(high_x) + 1),
          std::max(0, pixel(low_y) - 1),
          std::min(height - 1, pixel(high_y) + 1),
          {},
          {}};
}

bool empty(const AreaTruth::TriangleTruth& r) {
  return r.first_x > r.last_x || r.first_y > r.last_y;
}

/// Draws one triangle alone on the canvas (empty before and after), calling visit(k, value) for
/// the k-th pixel of its region, row by row from the bottom.
template <class Visit>
void draw_alone(const CoverageDraw& draw, ch09::CoverageCanvas& canvas, const SceneTriangle& t,
                const AreaTruth::TriangleTruth& r, Visit&& visit) {
  draw(canvas, std::span(&t, 1));
  std::size_t k = 0;
  for (int y = r.first_y; y <= r.last_y; ++y) {
    for (int x = r.first_x; x <= r.last_x; ++x, ++k) {
      visit(k, static_cast<double>(canvas.at(x, y)));
      canvas.set(x, y, 0.0f);  // the next triangle starts from an empty canvas
    }
  }
}

CoverageDraw draw_with(const ch09::AreaAlgorithm& algorithm) {
  return [&algorithm](ch09::CoverageCanvas& canvas, std::span<const SceneTriangle> triangles) {
    ch09::draw_coverage(algorithm, canvas, triangles);
  };
}

bool on_oracle_grid(const Triangle& t) {
  if (validate_triangle(t) != DrawResult::drawn) return false;
  try {
    ch09::require_on_oracle_grid(t);
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

AreaTruth::AreaTruth(const Scene& scene)
    : width_(scene.width),
      height_(scene.height),
      summed_(static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height), 0) {
  for (const auto& primitive : scene.primitives) {
    const auto* t = std::get_if<SceneTriangle>(&primitive);
    if (t == nullptr) continue;
    if (!on_oracle_grid(t->vertices)) {
      ++rejected_;
      continue;
    }
    TriangleTruth truth = region_of(t->vertices, width_, height_);
    if (!empty(truth)) {
      const auto region_width = static_cast<std::size_t>(truth.last_x - truth.first_x + 1);
      const std::size_t size =
          region_width * static_cast<std::size_t>(truth.last_y - truth.first_y + 1);
      truth.coverage.assign(size, 0.0);
      truth.units.assign(size, 0);
      for (const ch09::PixelCoverage& p : ch09::exact_coverages(t->vertices)) {
        if (p.pixel.x < truth.first_x || p.pixel.x > truth.last_x || p.pixel.y < truth.first_y ||
            p.pixel.y > truth.last_y)
          continue;
        const std::size_t k = static_cast<std::size_t>(p.pixel.y - truth.first_y) * region_width +
                              static_cast<std::size_t>(p.pixel.x - truth.first_x);
        truth.coverage[k] = p.coverage.to_double();
        truth.units[k] = ch09::coverage_16(p.coverage);
        summed_[static_cast<std::size_t>(p.pixel.y) * static_cast<std::size_t>(width_) +
                static_cast<std::size_t>(p.pixel.x)] += truth.coverage[k];
      }
    }
    triangles_.push_back(*t);
    truths_.push_back(std::move(truth));
  }
}

AreaErrorReport measure_area_error(const CoverageDraw& draw, const AreaTruth& truth) {
  AreaErrorReport report;
  report.triangles = truth.triangles().size();
  report.rejected = truth.rejected();
  ch09::CoverageCanvas canvas(truth.width(), truth.height());
  ch09::AreaDifferences each;
  for (std::size_t i = 0; i < truth.triangles().size(); ++i) {
    const AreaTruth::TriangleTruth& t = truth.truths()[i];
    if (empty(t)) continue;
    draw_alone(draw, canvas, truth.triangles()[i], t, [&](std::size_t k, double estimate) {
      if (!each.add(estimate, t.coverage[k])) return;
      report.max_units =
          std::max(report.max_units, std::abs(ch09::coverage_16(estimate) - int{t.units[k]}));
    });
  }
  const ch09::CoverageError alone = each.summary();
  report.pixels = alone.pixels;
  report.mean = alone.mean;
  report.rms = alone.rms;
  report.max = alone.max;

  draw(canvas, truth.triangles());
  ch09::AreaDifferences composed;
  std::size_t k = 0;
  for (int y = 0; y < truth.height(); ++y) {
    for (int x = 0; x < truth.width(); ++x, ++k) {
      const double estimate = std::clamp(static_cast<double>(canvas.at(x, y)), 0.0, 1.0);
      const double exact = std::clamp(truth.summed()[k], 0.0, 1.0);
      if (!composed.add(estimate, exact)) continue;
      report.composed_off_pixels +=
          std::abs(ch09::coverage_16(estimate) - ch09::coverage_16(exact)) > 1 ? 1 : 0;
    }
  }
  const ch09::CoverageError whole = composed.summary();
  report.composed_pixels = whole.pixels;
  report.composed_mean = whole.mean;
  report.composed_max = whole.max;
  return report;
}

AreaErrorReport measure_area_error(const CoverageDraw& draw, const Scene& scene) {
  return measure_area_error(draw, AreaTruth(scene));
}

AreaErrorReport measure_area_error(const ch09::AreaAlgorithm& algorithm, const Scene& scene) {
  return measure_area_error(draw_with(algorithm), scene);
}

std::uint64_t touched_pixels(const ch09::AreaAlgorithm& algorithm, int width, int height,
                             std::span<const SceneTriangle> triangles) {
  ch09::CoverageCanvas canvas(width, height);
  const CoverageDraw draw = draw_with(algorithm);
  std::uint64_t touched = 0;
  for (const SceneTriangle& t : triangles) {
    if (validate_triangle(t.vertices) != DrawResult::drawn) continue;
    const AreaTruth::TriangleTruth r = region_of(t.vertices, width, height);
    if (empty(r)) continue;
    draw_alone(draw, canvas, t, r, [&](std::size_t, double c) { touched += c != 0 ? 1 : 0; });
  }
  return touched;
}

}  // namespace tri
