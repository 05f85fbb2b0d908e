// A small rasterizer outside the book, for the conformance suite's own tests: it reads a scene
// file (docs/DESIGN.md section 4) and writes its write counts as a binary PGM, top row first, as
// `raster --counts` does, the way any program graded through --command must. It uses nothing of
// the book. Exact on the 1/256 grid (64-bit fixed point, 128-bit edge functions) with the
// top-left rule; --fault plants one mistake at a time, so the tests can see the suite catch it.
//
//   conformance_external_rasterizer [--fault NAME] SCENE COUNTS
//
// Faults: inclusive (every centre on an edge covered), bottom_right and bottom_left (those tie
// rules instead of top-left), snap4 (vertices snapped to 1/16 pixel), float_edges (edge functions
// in float), crash_on_nan (aborts on a NaN or infinite vertex), refuse_nan (exits 1 with a message
// on one), hang_on_nan (never ends on one), unreadable (writes text instead of a PGM).
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

struct Point {
  std::int64_t x, y;  // in 1/256 pixel
};

struct Options {
  std::string fault;
  std::string scene;
  std::string counts;
};

__extension__ using Wide = __int128;  // GCC and Clang have it on 64-bit targets

Wide edge(Point a, Point b, Point p, const Options& options) {
  if (options.fault == "float_edges") {
    const float ax = static_cast<float>(a.x), ay = static_cast<float>(a.y);
    const float e = (static_cast<float>(b.x) - ax) * (static_cast<float>(p.y) - ay) -
                    (static_cast<float>(b.y) - ay) * (static_cast<float>(p.x) - ax);
    return e > 0 ? 1 : (e < 0 ? -1 : 0);
  }
  return Wide{b.x - a.x} * (p.y - a.y) - Wide{b.y - a.y} * (p.x - a.x);
}

// Whether a centre exactly on edge a -> b of a counter-clockwise triangle (y up) is covered.
bool owns_ties(Point a, Point b, const Options& options) {
  const bool horizontal = a.y == b.y;
  if (options.fault == "inclusive") return true;
  if (options.fault == "bottom_left") return (horizontal && b.x > a.x) || b.y < a.y;
  if (options.fault == "bottom_right") return (horizontal && b.x > a.x) || b.y > a.y;
  return (horizontal && b.x < a.x) || b.y < a.y;  // top-left
}

std::int64_t fixed(double value, const Options& options) {
  if (options.fault == "snap4") return std::llround(value * 16) * 16;
  return std::llround(value * 256);
}

void draw(std::vector<std::uint32_t>& counts, int width, int height, std::array<double, 6> v,
          const Options& options) {
  std::array<Point, 3> t{};
  for (int i = 0; i < 3; ++i) t[i] = {fixed(v[2 * i], options), fixed(v[2 * i + 1], options)};
  const Wide area = edge(t[0], t[1], t[2], options);
  if (area == 0) return;
  if (area < 0) std::swap(t[1], t[2]);
  double low_x = 1e300, low_y = 1e300, high_x = -1e300, high_y = -1e300;
  for (const Point p : t) {
    low_x = std::min(low_x, p.x / 256.0);
    high_x = std::max(high_x, p.x / 256.0);
    low_y = std::min(low_y, p.y / 256.0);
    high_y = std::max(high_y, p.y / 256.0);
  }
  const int x0 = static_cast<int>(std::max(0.0, std::ceil(low_x)));
  const int x1 = static_cast<int>(std::min(width - 1.0, std::floor(high_x)));
  const int y0 = static_cast<int>(std::max(0.0, std::ceil(low_y)));
  const int y1 = static_cast<int>(std::min(height - 1.0, std::floor(high_y)));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Point p{std::int64_t{x} * 256, std::int64_t{y} * 256};
      bool inside = true;
      for (int i = 0; i < 3 && inside; ++i) {
        const Point a = t[i], b = t[(i + 1) % 3];
        const Wide e = edge(a, b, p, options);
        inside = e > 0 || (e == 0 && owns_ties(a, b, options));
      }
      if (inside) ++counts[static_cast<std::size_t>(y) * width + x];
    }
  }
}

int fail(const std::string& message) {
  std::cerr << "external_rasterizer: " << message << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 4 && args[0] == "--fault") {
    options.fault = args[1];
    args.erase(args.begin(), args.begin() + 2);
  }
  if (args.size() != 2) return fail("usage: [--fault NAME] SCENE COUNTS");
  options.scene = args[0];
  options.counts = args[1];
  std::ifstream in(options.scene);
  if (!in) return fail("cannot read " + options.scene);
  int width = 0, height = 0;
  std::vector<std::uint32_t> counts;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string directive;
    if (!(words >> directive) || directive[0] == '#') continue;
    if (directive == "canvas") {
      words >> width >> height;
      if (width < 1 || height < 1 || width > 16384 || height > 16384) return fail("bad canvas");
      counts.assign(static_cast<std::size_t>(width) * height, 0);
      continue;
    }
    if (directive != "tri" || counts.empty()) return fail("unexpected " + directive);
    std::array<double, 6> v{};
    bool finite = true;
    for (double& c : v) {
      std::string word;
      words >> word;
      c = std::strtod(word.c_str(), nullptr);  // reads nan, inf and -inf too
      finite = finite && std::isfinite(c);
    }
    if (!finite) {
      if (options.fault == "crash_on_nan") std::abort();
      if (options.fault == "refuse_nan") return fail("a vertex is not a finite number");
      if (options.fault == "hang_on_nan") {
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
      }
      continue;  // drawn as nothing
    }
    draw(counts, width, height, v, options);
  }
  std::ofstream out(options.counts, std::ios::binary);
  if (options.fault == "unreadable") {
    out << "these are not counts\n";
    return 0;
  }
  out << "P5\n" << width << " " << height << "\n255\n";
  for (int y = height - 1; y >= 0; --y) {
    for (int x = 0; x < width; ++x) {
      out.put(static_cast<char>(
          std::min<std::uint32_t>(counts[static_cast<std::size_t>(y) * width + x], 255)));
    }
  }
  return out.good() ? 0 : fail("cannot write " + options.counts);
}
