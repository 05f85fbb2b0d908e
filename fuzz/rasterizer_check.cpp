#include "fuzz/rasterizer_check.hpp"

#include <cmath>
#include <cstddef>
#include <locale>
#include <sstream>

#include "chapters/07_exact_coverage/coverage_oracle.hpp"
#include "fuzz/pixel_tally.hpp"

namespace tri::fuzz {
namespace {

// A background that differs from the triangle's colour in every channel, so a pixel's colour
// alone tells whether it was written (algorithms may write rows directly, uncounted).
Color background_for(Color color) noexcept {
  return {static_cast<std::uint8_t>(255 - color.r), static_cast<std::uint8_t>(255 - color.g),
          static_cast<std::uint8_t>(255 - color.b), 255};
}

class Checker {
 public:
  Checker(const TriangleAlgorithm& algorithm, const RasterizerInput& input, Findings& findings)
      : algorithm_(algorithm), input_(input), findings_(findings) {}

  void check_one_triangle(std::size_t index) {
    const SceneTriangle& t = input_.triangles[index];
    const Color background = background_for(t.color);
    Canvas canvas(input_.width, input_.height, background);
    canvas.enable_write_counts();
    const DrawResult result = draw_triangle(algorithm_, canvas, t.vertices, t.color);
    const std::string where =
        context() + ", triangle " + std::to_string(index) + " (" + scene_line(t) + ")";
    if (canvas.outside_writes() != 0) {
      findings_.push_back(where + ": " + std::to_string(canvas.outside_writes()) +
                          " writes outside the canvas");
    }
    PixelTally changed;     // refused, yet written
    PixelTally foreign;     // neither the background nor the triangle's colour
    PixelTally miscolored;  // counted as written, yet not in the triangle's colour
    for (int y = 0; y < canvas.height(); ++y) {
      for (int x = 0; x < canvas.width(); ++x) {
        const Color c = canvas.pixel(x, y);
        if (result != DrawResult::drawn && (c != background || canvas.write_count(x, y) != 0)) {
          changed.add(x, y);
        }
        if (c != background && c != t.color) foreign.add(x, y);
        if (canvas.write_count(x, y) != 0 && c != t.color) miscolored.add(x, y);
      }
    }
    report_pixels(findings_, where + ": " + std::string(describe(result)) + ", yet pixels changed",
                  changed);
    report_pixels(findings_,
                  where + ": pixels in a colour that is neither the background nor the triangle's",
                  foreign);
    report_pixels(findings_, where + ": pixels counted as written but not in the triangle's colour",
                  miscolored);
    if (result == DrawResult::drawn && algorithm_.rule == CoverageRule::top_left &&
        on_subpixel_grid(t.vertices)) {
      compare_with_oracle(canvas, t, where);
    }
  }

  void check_batch() {
    Canvas one_by_one(input_.width, input_.height, colors::black);
    std::size_t refused = 0;
    for (const SceneTriangle& t : input_.triangles) {
      refused += draw_triangle(algorithm_, one_by_one, t.vertices, t.color) != DrawResult::drawn;
    }
    Canvas batch(input_.width, input_.height, colors::black);
    batch.enable_write_counts();
    const std::size_t batch_refused = draw_triangles(algorithm_, batch, input_.triangles);
    const std::string where = context() + ", draw_triangles with " +
                              std::to_string(input_.triangles.size()) + " triangles";
    if (batch.outside_writes() != 0) {
      findings_.push_back(where + ": " + std::to_string(batch.outside_writes()) +
                          " writes outside the canvas");
    }
    if (batch_refused != refused) {
      findings_.push_back(where + ": refused " + std::to_string(batch_refused) + ", one by one " +
                          std::to_string(refused));
    }
    PixelTally different;
    for (int y = 0; y < batch.height(); ++y) {
      for (int x = 0; x < batch.width(); ++x) {
        if (batch.pixel(x, y) != one_by_one.pixel(x, y)) different.add(x, y);
      }
    }
    report_pixels(findings_, where + ": pixels differ from drawing them one by one", different);
  }

 private:
  std::string context() const {
    return std::string(algorithm_.name) + " on a " + std::to_string(input_.width) + "x" +
           std::to_string(input_.height) + " canvas";
  }

  void compare_with_oracle(const Canvas& canvas, const SceneTriangle& t, const std::string& where) {
    Canvas oracle(canvas.width(), canvas.height(), background_for(t.color));
    ch07::draw_triangle_oracle(oracle, t.vertices, t.color);
    PixelTally missed;
    PixelTally extra;
    for (int y = 0; y < canvas.height(); ++y) {
      for (int x = 0; x < canvas.width(); ++x) {
        const bool drawn = canvas.pixel(x, y) == t.color;
        const bool covered = oracle.pixel(x, y) == t.color;
        if (covered && !drawn) missed.add(x, y);
        if (drawn && !covered) extra.add(x, y);
      }
    }
    if (missed.count() != 0 || extra.count() != 0) {
      findings_.push_back(
          where + ": top-left rule on the 1/256 grid, yet not the oracle's pixels: " + "missed " +
          missed.text() + "; extra " + extra.text());
    }
  }

  const TriangleAlgorithm& algorithm_;
  const RasterizerInput& input_;
  Findings& findings_;
};

}  // namespace

bool on_subpixel_grid(const Triangle& triangle) noexcept {
  for (const glm::dvec2& v : triangle) {
    for (const double c : {v.x, v.y}) {
      // Scaling by 256 is exact for finite doubles below 2^1015, so this tests c itself.
      if (!std::isfinite(c) || std::abs(c) > max_scene_coordinate) return false;
      if (std::floor(c * 256.0) != c * 256.0) return false;
    }
  }
  return true;
}

std::string scene_line(const SceneTriangle& triangle) {
  std::ostringstream line;
  line.imbue(std::locale::classic());
  line.precision(17);  // enough digits to read back the same double
  line << "tri";
  for (const glm::dvec2& v : triangle.vertices) line << ' ' << v.x << ' ' << v.y;
  line << ' ' << int{triangle.color.r} << ' ' << int{triangle.color.g} << ' '
       << int{triangle.color.b};
  return line.str();
}

Findings check_rasterizer(const TriangleAlgorithm& algorithm, const RasterizerInput& input) {
  Findings findings;
  Checker checker(algorithm, input, findings);
  for (std::size_t i = 0; i < input.triangles.size(); ++i) checker.check_one_triangle(i);
  if (algorithm.draw_batch != nullptr || algorithm.make_renderer != nullptr || algorithm.threaded)
    checker.check_batch();
  return findings;
}

}  // namespace tri::fuzz
