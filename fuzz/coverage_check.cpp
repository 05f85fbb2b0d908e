#include "fuzz/coverage_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "chapters/09_anti_aliasing/area_oracle.hpp"
#include "chapters/09_anti_aliasing/sampling.hpp"
#include "fuzz/pixel_tally.hpp"

namespace tri::fuzz {
namespace {

constexpr double tolerance = 1e-6;      // chapter 09's promise for the exact-area algorithms
constexpr double oracle_reach = 32768;  // require_on_oracle_grid's ±2^15

// The triangle moved to the nearest points of the 1/256 grid, if every vertex is within
// oracle_grid_distance of one and within the oracle's reach; with how far the farthest moved.
struct GridTriangle {
  Triangle vertices;
  double moved = 0;
};

std::optional<GridTriangle> near_oracle_grid(const Triangle& t) {
  GridTriangle grid;
  for (std::size_t k = 0; k < 3; ++k) {
    for (int axis = 0; axis < 2; ++axis) {
      const double c = t[k][axis], snapped = std::round(c * 256) / 256;
      if (!(std::abs(snapped) <= oracle_reach)) return std::nullopt;
      grid.moved = std::max(grid.moved, std::abs(c - snapped));
      grid.vertices[k][axis] = snapped;
    }
  }
  if (grid.moved > oracle_grid_distance) return std::nullopt;
  return grid;
}

double perimeter(const Triangle& t) {
  return glm::length(t[1] - t[0]) + glm::length(t[2] - t[1]) + glm::length(t[0] - t[2]);
}

class Checker {
 public:
  Checker(const ch09::AreaAlgorithm& algorithm, const RasterizerInput& input, Findings& findings)
      : algorithm_(algorithm), input_(input), findings_(findings) {}

  // Draws triangle `index` alone, checks it, and returns its canvas.
  ch09::CoverageCanvas check_one_triangle(std::size_t index, std::size_t& refused) {
    const SceneTriangle& t = input_.triangles[index];
    ch09::CoverageCanvas canvas(input_.width, input_.height);
    const bool drawn = validate_triangle(t.vertices) == DrawResult::drawn;
    const std::size_t refusals = ch09::draw_coverage(algorithm_, canvas, {&t, 1});
    refused += refusals;
    const std::string where =
        context() + ", triangle " + std::to_string(index) + " (" + scene_line(t) + ")";
    if (refusals != (drawn ? 0u : 1u)) {
      findings_.push_back(where + ": draw_coverage refused " + std::to_string(refusals));
    }
    PixelTally changed, out_of_range;
    for (int y = 0; y < canvas.height(); ++y) {
      for (int x = 0; x < canvas.width(); ++x) {
        const float c = canvas.at(x, y);
        if (!drawn && c != 0) changed.add(x, y);
        if (!(c >= -tolerance && c <= 1 + tolerance)) out_of_range.add(x, y);
      }
    }
    report_pixels(findings_, where + ": refused, yet pixels changed", changed);
    report_pixels(findings_, where + ": coverage outside [0, 1] or not finite", out_of_range);
    if (drawn) compare_with_truth(canvas, t.vertices, where);
    return canvas;
  }

  // All triangles at once against the triangles drawn alone, summed or composited in order.
  void check_together(const std::vector<ch09::CoverageCanvas>& alone, std::size_t refused) {
    ch09::CoverageCanvas together(input_.width, input_.height);
    const std::size_t together_refused =
        ch09::draw_coverage(algorithm_, together, input_.triangles);
    const std::string where = context() + ", draw_coverage with " +
                              std::to_string(input_.triangles.size()) + " triangles";
    if (together_refused != refused) {
      findings_.push_back(where + ": refused " + std::to_string(together_refused) +
                          ", one by one " + std::to_string(refused));
    }
    const bool over = algorithm_.composites_over;
    const double allowed =
        algorithm_.sample_pattern ? 0 : tolerance * static_cast<double>(alone.size());
    PixelTally differs;
    for (int y = 0; y < together.height(); ++y) {
      for (int x = 0; x < together.width(); ++x) {
        float expected = 0;
        for (const ch09::CoverageCanvas& canvas : alone) {
          const float c = canvas.at(x, y);
          expected = over ? expected + c * (1.0f - expected) : expected + c;
        }
        if (!(std::abs(together.at(x, y) - expected) <= allowed)) differs.add(x, y);
      }
    }
    report_pixels(findings_, where + ": pixels unlike the triangles drawn one by one", differs);
  }

 private:
  std::string context() const {
    return std::string(algorithm_.name) + " on " + std::to_string(input_.width) + "x" +
           std::to_string(input_.height);
  }

  // Exact area (where the oracle knows it) or the exact count of the algorithm's own samples.
  void compare_with_truth(const ch09::CoverageCanvas& canvas, const Triangle& t,
                          const std::string& where) {
    PixelTally wrong;
    // Beyond a pixel of the triangle's box the truth is 0: the exact answers are asked only near.
    glm::dvec2 low = t[0], high = t[0];
    for (const glm::dvec2& v : t) {
      low = glm::min(low, v);
      high = glm::max(high, v);
    }
    const auto near = [&](int x, int y) {
      return x >= low.x - 1 && x <= high.x + 1 && y >= low.y - 1 && y <= high.y + 1;
    };
    if (algorithm_.sample_pattern != nullptr) {
      const ch09::SamplePattern pattern = algorithm_.sample_pattern();
      for (int y = 0; y < canvas.height(); ++y) {
        for (int x = 0; x < canvas.width(); ++x) {
          const double truth =
              near(x, y) ? ch09::snapped_sampled_coverage(t, {x, y}, pattern) : 0.0;
          if (canvas.at(x, y) != truth) wrong.add(x, y);
        }
      }
    } else {
      const std::optional<GridTriangle> grid = near_oracle_grid(t);
      if (!grid) return;
      const double allowed = tolerance + 4 * grid->moved * (perimeter(grid->vertices) + 1);
      try {
        for (int y = 0; y < canvas.height(); ++y) {
          for (int x = 0; x < canvas.width(); ++x) {
            const double exact =
                near(x, y) ? ch09::exact_coverage(grid->vertices, {x, y}).to_double() : 0.0;
            if (!(std::abs(canvas.at(x, y) - exact) <= allowed)) wrong.add(x, y);
          }
        }
      } catch (const std::overflow_error&) {
        return;  // a triangle too large for the oracle's 128-bit fractions: no truth to compare
      }
    }
    report_pixels(findings_,
                  where + (algorithm_.sample_pattern ? ": unlike its own samples' count"
                                                     : ": unlike the exact area"),
                  wrong);
  }

  const ch09::AreaAlgorithm& algorithm_;
  const RasterizerInput& input_;
  Findings& findings_;
};

}  // namespace

RasterizerInput coverage_input(RasterizerInput input) {
  input.width = (input.width - 1) % max_coverage_canvas_side + 1;
  input.height = (input.height - 1) % max_coverage_canvas_side + 1;
  return input;
}

Findings check_coverage(const ch09::AreaAlgorithm& algorithm, const RasterizerInput& input) {
  Findings findings;
  Checker checker(algorithm, input, findings);
  std::vector<ch09::CoverageCanvas> alone;
  std::size_t refused = 0;
  for (std::size_t i = 0; i < input.triangles.size(); ++i) {
    alone.push_back(checker.check_one_triangle(i, refused));
  }
  if (input.triangles.size() > 1) checker.check_together(alone, refused);
  return findings;
}

}  // namespace tri::fuzz
