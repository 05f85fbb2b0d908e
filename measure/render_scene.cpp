#include "measure/render_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "chapters/01_lines/lines.hpp"

namespace tri {
namespace {

using Clock = std::chrono::steady_clock;

// With progress, pieces of a run grow while they draw quickly and shrink when one takes long, so a
// report comes about every tenth of a second whether the triangles are tiny or cover the canvas.
class PieceSize {
 public:
  std::size_t value() const noexcept { return size_; }
  void after(Clock::duration took) noexcept {
    if (took < std::chrono::milliseconds(50) && size_ < 65536) size_ *= 2;
    if (took > std::chrono::milliseconds(200) && size_ > 1) size_ /= 2;
  }

 private:
  std::size_t size_ = 1;
};

// The rows a triangle's bounding box covers on a canvas of `height` rows, and its pixel count
// (0 when it misses the canvas).
struct RowBox {
  int first_row = 0;
  int last_row = -1;
  double pixels = 0;
};

RowBox row_box(const Triangle& t, int width, int height) {
  const auto [low_x, high_x] = std::minmax({t[0].x, t[1].x, t[2].x});
  const auto [low_y, high_y] = std::minmax({t[0].y, t[1].y, t[2].y});
  const double x0 = std::max(std::floor(low_x), 0.0), x1 = std::min(std::ceil(high_x), width - 1.0);
  const double y0 = std::max(std::floor(low_y), 0.0),
               y1 = std::min(std::ceil(high_y), height - 1.0);
  if (x0 > x1 || y0 > y1) return {};
  return {static_cast<int>(y0), static_cast<int>(y1), (x1 - x0 + 1) * (y1 - y0 + 1)};
}

// A scene's line: chapter 01's Bresenham between the nearest pixel centres.
void draw_line(Canvas& canvas, const SceneLine& line) {
  ch01::draw_line_bresenham(canvas, nearest_pixel(line.ends[0]), nearest_pixel(line.ends[1]),
                            line.color);
}

BatchDrawer& drawer_for_triangles(BatchDrawer* drawer) {
  if (drawer == nullptr) throw std::logic_error("the scene has triangles but no algorithm");
  return *drawer;
}

}  // namespace

Canvas make_canvas(const Scene& scene) {
  return Canvas(scene.width, scene.height, scene.background);
}

std::size_t count_triangles(const Scene& scene) {
  std::size_t n = 0;
  for (const auto& primitive : scene.primitives)
    n += std::holds_alternative<SceneTriangle>(primitive);
  return n;
}

std::vector<SceneTriangle> scene_triangles(const Scene& scene) {
  std::vector<SceneTriangle> triangles;
  for (const auto& primitive : scene.primitives) {
    if (const auto* t = std::get_if<SceneTriangle>(&primitive)) triangles.push_back(*t);
  }
  return triangles;
}

int band_rows_for(const Triangle& t, int width, int height) {
  const RowBox box = row_box(t, width, height);
  if (box.pixels <= static_cast<double>(band_pixels)) return 0;
  const double columns = box.pixels / (box.last_row - box.first_row + 1);
  return std::max(1, static_cast<int>(static_cast<double>(band_pixels) / columns));
}

void for_each_band(const Triangle& t, int width, int height, int rows,
                   const std::function<void(int first_row, int last_row)>& draw_rows,
                   const std::function<void(double share)>& after_band) {
  const RowBox box = row_box(t, width, height);
  const int first = box.last_row < box.first_row ? 0 : box.first_row;
  const int last = box.last_row < box.first_row ? height - 1 : box.last_row;
  rows = std::max(rows, 1);
  int begin = 0;
  for (int start = first;; start += rows) {
    const int end = last - start < rows ? height - 1 : start + rows - 1;
    draw_rows(begin, end);
    if (after_band)
      after_band(std::min(1.0, static_cast<double>(end - first + 1) / (last - first + 1)));
    if (end == height - 1) return;
    begin = end + 1;
  }
}

RenderStats render_scene(const Scene& scene, BatchDrawer* drawer, Canvas& canvas,
                         const ProgressFunction& on_progress) {
  RenderStats stats;
  // Consecutive triangles are drawn as one batch, so a batch algorithm sees them together.
  std::vector<SceneTriangle> run;
  std::size_t done = 0;
  PieceSize piece;
  const auto flush = [&] {
    if (run.empty()) return;
    const auto start = Clock::now();
    const std::size_t refused = drawer_for_triangles(drawer).draw(canvas, run);
    stats.rejected_triangles += refused;
    stats.triangles += run.size() - refused;
    run.clear();
    if (!on_progress) return;
    piece.after(Clock::now() - start);
    on_progress(static_cast<double>(done));
  };
  // With progress, a huge triangle is drawn on its own in bands of rows, a report after each.
  const auto banded = [&](const SceneTriangle& t) {
    if (!on_progress || drawer == nullptr || drawer->algorithm().draw_rows == nullptr ||
        validate_triangle(t.vertices) != DrawResult::drawn) {
      return false;
    }
    const int rows = band_rows_for(t.vertices, canvas.width(), canvas.height());
    if (rows == 0) return false;
    flush();
    const double before = static_cast<double>(done);
    const TriangleAlgorithm& algorithm = drawer->algorithm();
    for_each_band(
        t.vertices, canvas.width(), canvas.height(), rows,
        [&](int first, int last) { algorithm.draw_rows(canvas, t.vertices, t.color, first, last); },
        [&](double share) { on_progress(before + share); });
    ++stats.triangles;
    return true;
  };
  for (const auto& primitive : scene.primitives) {
    if (const auto* triangle = std::get_if<SceneTriangle>(&primitive)) {
      if (banded(*triangle)) {
        ++done;
        continue;
      }
      run.push_back(*triangle);
      ++done;
      if (on_progress && run.size() >= piece.value()) flush();
    } else {
      flush();
      draw_line(canvas, std::get<SceneLine>(primitive));
      ++stats.lines;
      ++done;
      if (on_progress && done % 4096 == 0) on_progress(static_cast<double>(done));
    }
  }
  flush();
  return stats;
}

PreparedDrawing prepare_drawing(const Scene& scene) {
  PreparedDrawing prepared;
  const CanvasExtent canvas{scene.width, scene.height};
  const auto& primitives = scene.primitives;
  for (auto primitive = primitives.begin(); primitive != primitives.end();) {
    if (const auto* line = std::get_if<SceneLine>(&*primitive)) {
      prepared.steps.emplace_back(*line);
      ++prepared.stats.lines;
      ++primitive;
      continue;
    }
    // A run's batch is allocated once, for all the triangles up to the next line: the pages of
    // those it culls are never touched, so they cost address space, not memory or time.
    const auto run_end = std::find_if(primitive, primitives.end(), [](const auto& p) {
      return std::holds_alternative<SceneLine>(p);
    });
    PreparedBatch batch(canvas);
    batch.reserve(static_cast<std::size_t>(run_end - primitive));
    for (; primitive != run_end; ++primitive) {
      const bool drawn = batch.add(std::get<SceneTriangle>(*primitive)) == DrawResult::drawn;
      ++(drawn ? prepared.stats.triangles : prepared.stats.rejected_triangles);
    }
    prepared.steps.emplace_back(std::move(batch));
  }
  return prepared;
}

RenderStats draw_prepared(const PreparedDrawing& prepared, BatchDrawer* drawer, Canvas& canvas) {
  for (const auto& step : prepared.steps) {
    if (const auto* batch = std::get_if<PreparedBatch>(&step)) {
      drawer_for_triangles(drawer).draw(canvas, *batch);
    } else {
      draw_line(canvas, std::get<SceneLine>(step));
    }
  }
  return prepared.stats;
}

RenderStats render_scene(const Scene& scene, const TriangleAlgorithm* algorithm, Canvas& canvas,
                         const ProgressFunction& on_progress) {
  if (algorithm == nullptr)
    return render_scene(scene, static_cast<BatchDrawer*>(nullptr), canvas, on_progress);
  BatchDrawer drawer(*algorithm);
  return render_scene(scene, &drawer, canvas, on_progress);
}

std::size_t render_coverage(const Scene& scene, const ch09::AreaAlgorithm& algorithm,
                            ch09::CoverageCanvas& canvas, const ProgressFunction& on_progress) {
  std::size_t refused = 0;
  std::vector<SceneTriangle> run;  // a piece of the scene's triangles, never all of them
  std::size_t done = 0;
  PieceSize piece;
  const auto flush = [&] {
    if (run.empty()) return;
    const auto start = Clock::now();
    refused += ch09::draw_coverage(algorithm, canvas, run);
    run.clear();
    piece.after(Clock::now() - start);
    if (on_progress) on_progress(static_cast<double>(done));
  };
  for (const auto& primitive : scene.primitives) {
    ++done;
    const auto* triangle = std::get_if<SceneTriangle>(&primitive);
    if (triangle == nullptr) continue;  // a line has no area
    const int rows = on_progress && algorithm.draw_rows != nullptr &&
                             validate_triangle(triangle->vertices) == DrawResult::drawn
                         ? band_rows_for(triangle->vertices, canvas.width(), canvas.height())
                         : 0;
    if (rows > 0) {
      flush();
      const double before = static_cast<double>(done - 1);
      for_each_band(
          triangle->vertices, canvas.width(), canvas.height(), rows,
          [&](int first, int last) {
            algorithm.draw_rows(canvas, triangle->vertices, first, last);
          },
          [&](double share) { on_progress(before + share); });
      continue;
    }
    run.push_back(*triangle);
    if (run.size() >= piece.value()) flush();
  }
  flush();
  return refused;
}

}  // namespace tri
