#include "measure/area_error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "chapters/10_coverage/area_oracle.hpp"

namespace tri {
namespace {

/// The pixels a triangle can reach (its bounding box and one pixel around it) on the canvas.
struct Region {
  int first_x, last_x, first_y, last_y;
  bool empty() const noexcept { return first_x > last_x || first_y > last_y; }
};

Region region_of(const Triangle& t, int width, int height) {
  const auto [low_x, high_x] = std::minmax({t[0].x, t[1].x, t[2].x});
  const auto [low_y, high_y] = std::minmax({t[0].y, t[1].y, t[2].y});
  const auto pixel = [](double v) { return static_cast<int>(std::floor(v + 0.5)); };
  return {std::max(0, pixel(low_x) - 1), std::min(width - 1, pixel(high_x) + 1),
          std::max(0, pixel(low_y) - 1), std::min(height - 1, pixel(high_y) + 1)};
}

/// Sums of absolute differences, for a mean, an RMS and a maximum.
struct Differences {
  std::uint64_t count = 0;
  double sum = 0, sum_of_squares = 0, max = 0;

  void add(double difference) {
    ++count;
    sum += difference;
    sum_of_squares += difference * difference;
    max = std::max(max, difference);
  }
  double mean() const { return count == 0 ? 0 : sum / static_cast<double>(count); }
  double rms() const {
    return count == 0 ? 0 : std::sqrt(sum_of_squares / static_cast<double>(count));
  }
};

// Draws one triangle alone on the canvas (empty before and after), calling visit(x, y, value) on
// every pixel of its region.
template <class Visit>
void draw_alone(const CoverageDraw& draw, ch10::CoverageCanvas& canvas, const SceneTriangle& t,
                const Region& r, Visit&& visit) {
  draw(canvas, std::span(&t, 1));
  for (int y = r.first_y; y <= r.last_y; ++y) {
    for (int x = r.first_x; x <= r.last_x; ++x) {
      visit(x, y, static_cast<double>(canvas.at(x, y)));
      canvas.set(x, y, 0.0f);  // the next triangle starts from an empty canvas
    }
  }
}

CoverageDraw draw_with(const ch10::AreaAlgorithm& algorithm) {
  return [&algorithm](ch10::CoverageCanvas& canvas, std::span<const SceneTriangle> triangles) {
    ch10::draw_coverage(algorithm, canvas, triangles);
  };
}

bool on_oracle_grid(const Triangle& t) {
  try {
    ch10::require_on_oracle_grid(t);
    return validate_triangle(t) == DrawResult::drawn;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

AreaErrorReport measure_area_error(const CoverageDraw& draw, const Scene& scene) {
  AreaErrorReport report;
  ch10::CoverageCanvas canvas(scene.width, scene.height);
  const auto w = static_cast<std::size_t>(scene.width);
  std::vector<double> exact_sum(w * static_cast<std::size_t>(scene.height), 0.0);
  std::vector<SceneTriangle> kept;
  Differences each;
  for (const auto& primitive : scene.primitives) {
    const auto* t = std::get_if<SceneTriangle>(&primitive);
    if (t == nullptr) continue;
    if (!on_oracle_grid(t->vertices)) {
      ++report.rejected;
      continue;
    }
    kept.push_back(*t);
    ++report.triangles;
    const Region r = region_of(t->vertices, scene.width, scene.height);
    if (r.empty()) continue;
    // The exact coverages of the region's pixels, as values and as 16-bit outputs.
    const auto rw = static_cast<std::size_t>(r.last_x - r.first_x + 1);
    std::vector<double> exact(rw * static_cast<std::size_t>(r.last_y - r.first_y + 1), 0.0);
    std::vector<int> exact_units(exact.size(), 0);
    for (const ch10::PixelCoverage& p : ch10::exact_coverages(t->vertices)) {
      if (p.pixel.x < r.first_x || p.pixel.x > r.last_x || p.pixel.y < r.first_y ||
          p.pixel.y > r.last_y)
        continue;
      const std::size_t k = static_cast<std::size_t>(p.pixel.y - r.first_y) * rw +
                            static_cast<std::size_t>(p.pixel.x - r.first_x);
      exact[k] = p.coverage.to_double();
      exact_units[k] = ch10::coverage_16(p.coverage);
      exact_sum[static_cast<std::size_t>(p.pixel.y) * w + static_cast<std::size_t>(p.pixel.x)] +=
          exact[k];
    }
    draw(canvas, std::span(t, 1));
    for (int y = r.first_y; y <= r.last_y; ++y) {
      for (int x = r.first_x; x <= r.last_x; ++x) {
        const std::size_t k =
            static_cast<std::size_t>(y - r.first_y) * rw + static_cast<std::size_t>(x - r.first_x);
        const double estimate = canvas.at(x, y);
        if (estimate != 0 || exact[k] != 0) {
          each.add(std::abs(estimate - exact[k]));
          report.max_units =
              std::max(report.max_units, std::abs(ch10::coverage_16(estimate) - exact_units[k]));
        }
        canvas.set(x, y, 0.0f);  // the next triangle starts from an empty canvas
      }
    }
  }
  report.pixels = each.count;
  report.mean = each.mean();
  report.rms = each.rms();
  report.max = each.max;

  draw(canvas, kept);
  Differences composed;
  for (int y = 0; y < scene.height; ++y) {
    for (int x = 0; x < scene.width; ++x) {
      const double estimate = std::clamp(static_cast<double>(canvas.at(x, y)), 0.0, 1.0);
      const double truth = std::clamp(
          exact_sum[static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x)], 0.0, 1.0);
      if (estimate == 0 && truth == 0) continue;
      composed.add(std::abs(estimate - truth));
      report.composed_off_pixels +=
          std::abs(ch10::coverage_16(estimate) - ch10::coverage_16(truth)) > 1 ? 1 : 0;
    }
  }
  report.composed_pixels = composed.count;
  report.composed_mean = composed.mean();
  report.composed_max = composed.max;
  return report;
}

AreaErrorReport measure_area_error(const ch10::AreaAlgorithm& algorithm, const Scene& scene) {
  return measure_area_error(draw_with(algorithm), scene);
}

std::uint64_t touched_pixels(const ch10::AreaAlgorithm& algorithm, int width, int height,
                             std::span<const SceneTriangle> triangles) {
  ch10::CoverageCanvas canvas(width, height);
  const CoverageDraw draw = draw_with(algorithm);
  std::uint64_t touched = 0;
  for (const SceneTriangle& t : triangles) {
    if (validate_triangle(t.vertices) != DrawResult::drawn) continue;
    const Region r = region_of(t.vertices, width, height);
    if (r.empty()) continue;
    draw_alone(draw, canvas, t, r, [&](int, int, double c) { touched += c != 0 ? 1 : 0; });
  }
  return touched;
}

}  // namespace tri
