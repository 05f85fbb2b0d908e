#include "chapters/09_anti_aliasing/area_cells.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

#include "common/scene.hpp"

namespace tri::ch09 {
namespace {

// Pixel i spans [i - 1/2, i + 1/2): the column an x lies in.
// (std::floor is a library call on baseline x86-64; this is floor for |x| < 2^31.)
int column_of(double x) {
  const double shifted = x + 0.5;
  const auto truncated = static_cast<int>(shifted);
  return truncated > shifted ? truncated - 1 : truncated;
}

// Calls visit(column, area, height) for every cell from first to last (the columns of the
// segment's left and right ends, both on the canvas), left to right: the height of the segment's
// part in the cell and the area between that part and the cell's right side. Across several
// cells the height is shared in proportion to the width crossed, k per unit of x: the first and
// last cells get a part, every cell between the whole k, and its area is k / 2.
template <class Visit>
void for_each_cell(double x0, double y0, double x1, double y1, double dy_dx, int first, int last,
                   Visit&& visit) {
  const double height = y1 - y0;
  if (first == last) return visit(first, height * ((first + 0.5) - (x0 + x1) / 2), height);
  const double k = std::copysign(std::abs(dy_dx), height);
  const double w0 = (first + 0.5) - std::min(x0, x1);  // the width crossed in the first cell
  const double h0 = k * w0;
  visit(first, h0 * (w0 / 2), h0);
  double rest = height - h0;
  for (int column = first + 1; column < last; ++column) {
    visit(column, k / 2, k);
    rest -= k;
  }
  const double w1 = std::max(x0, x1) - (last - 0.5);  // the width crossed in the last cell
  visit(last, rest * (1 - w1 / 2), rest);
}

}  // namespace

void RowCells::start_row(int width) {
  if (cells_.size() < static_cast<std::size_t>(width) + 1) {
    cells_.assign(static_cast<std::size_t>(width) + 1, Cell{});
  }
  for (const Touched& t : touched_) {  // cells read but not added to a canvas (figures, tests)
    if (t.first <= t.last) std::fill(cells_.begin() + t.first, cells_.begin() + t.last + 1, Cell{});
  }
  width_ = width;
  touched_ = {};
}

// [listing add_piece]
// A piece of an edge inside one cell: the area between it and the cell's right side goes to the
// cell, and its height to the covers of the cells to its right. Left of the canvas only the cover
// matters (it reaches column 0); right of the canvas nothing does, but the row must then be summed
// up to the canvas's last column. The touched columns bound the row's sum.
inline void RowCells::add_piece(Touched& touched, int column, double xa, double ya, double xb,
                                double yb) {
  const double height = yb - ya;
  if (column < 0) {
    cells_[0].cover += height;
    touched.first = std::min(touched.first, 0);
    touched.last = std::max(touched.last, 0);
  } else if (column < width_) {
    cells_[column].area += height * ((column + 0.5) - (xa + xb) / 2);
    cells_[column + 1].cover += height;
    touched.first = std::min(touched.first, column);
    touched.last = std::max(touched.last, column + 1);
  } else {
    touched.last = std::max(touched.last, width_);  // the row is summed to the canvas's end
  }
}
// [/listing]

void RowCells::add_segment(Side side, double x0, double y0, double x1, double y1, double dy_dx) {
  Touched& touched = touched_[static_cast<std::size_t>(side)];
  const int first = column_of(std::min(x0, x1)), last = column_of(std::max(x0, x1));
  if (first < 0 || last >= width_) return add_segment_walk(touched, x0, y0, x1, y1, dy_dx);
  touched.first = std::min(touched.first, first);
  touched.last = std::max(touched.last, last + 1);
  for_each_cell(x0, y0, x1, y1, dy_dx, first, last, [&](int column, double area, double height) {
    cells_[column].area += area;
    cells_[column + 1].cover += height;
  });
}

void RowCells::add_segment_walk(Touched& touched, double x0, double y0, double x1, double y1,
                                double dy_dx) {
  // Clip the walk to the columns that matter: everything left of the canvas is one cover.
  const double left = -0.5, right = width_ - 0.5;
  if (x0 < left && x1 < left) return add_piece(touched, -1, x0, y0, x1, y1);
  if (x0 >= right && x1 >= right) return add_piece(touched, width_, x0, y0, x1, y1);
  if (x0 == x1) return add_piece(touched, std::clamp(column_of(x0), -1, width_), x0, y0, x1, y1);
  const int step = x1 > x0 ? 1 : -1;
  int column = column_of(x0);
  if (step < 0 && x0 == column - 0.5) --column;  // leaving leftwards from a cell's left side
  int last = column_of(x1);
  if (step > 0 && x1 == last - 0.5) --last;  // arriving at a cell's left side from the left
  column = std::clamp(column, -1, width_);
  last = std::clamp(last, -1, width_);
  double xs = x0, ys = y0;
  while (column != last) {
    const double side = step > 0 ? column + 0.5 : column - 0.5;  // the side it leaves through
    const double y_side = y0 + (side - x0) * dy_dx;
    add_piece(touched, column, xs, ys, side, y_side);
    xs = side;
    ys = y_side;
    column += step;
  }
  add_piece(touched, column, xs, ys, x1, y1);
}

// [listing add_to_canvas]
// The cells first..last (within the canvas) summed from the left onto the row: the running cover
// plus each cell's own area. Empties the cells it reads; returns the cover after them.
template <class Put>
double RowCells::sum_cells(float* row, int first, int last, double cover, Put put) {
  for (int x = first; x <= last; ++x) {
    Cell& cell = cells_[static_cast<std::size_t>(x)];
    cover += cell.cover;
    const double coverage = -(cover + cell.area);  // a counter-clockwise outline sums to -area
    cell = {};                                     // ready for the next row
    if (coverage != 0) put(row[x], static_cast<float>(coverage));
  }
  return cover;
}

template <class Put>
void RowCells::sum_along_row(float* row, Put put) {
  Touched a = touched_[0], b = touched_[1];
  if (b.first < a.first) std::swap(a, b);  // a starts first (an empty side starts at INT_MAX)
  if (a.first > a.last) return;            // no side touched a cell
  const int end = width_ - 1;              // the canvas's last column
  if (b.first > b.last || b.first <= a.last + 1) {  // one side, or the sides' cells meet
    sum_cells(row, a.first, std::min(std::max(a.last, b.last), end), 0.0, put);
  } else {
    // Between the sides no cell holds anything: the cover alone, the same for every pixel.
    const double cover = sum_cells(row, a.first, std::min(a.last, end), 0.0, put);
    const auto between = static_cast<float>(-cover);
    for (int x = a.last + 1; x < std::min(b.first, width_); ++x) put(row[x], between);
    sum_cells(row, b.first, std::min(b.last, end), cover, put);
  }
}

void RowCells::add_to_canvas(CoverageCanvas& canvas, int y, Blend blend) {
  float* row = canvas.row(y);
  // One pass per blend, so the loop does not decide the blend at every pixel.
  if (blend == Blend::sum) {
    sum_along_row(row, [](float& v, float c) { v += c; });
  } else {
    sum_along_row(row, [](float& v, float c) { v += c * (1.0f - v); });
  }
  cells_[static_cast<std::size_t>(width_)] = {};  // a piece right of the canvas touched only this
  touched_ = {};
}
// [/listing]

namespace {

// The part of a triangle inside one pixel row between heights y0 < y1 where each side is one
// straight piece: the left side rises from x = left0 at y0 to left1 at y1, the right side from
// right0 to right1.
struct Band {
  double y0, y1, left0, left1, right0, right1, left_dy_dx, right_dy_dx;
  int left_first, left_last, right_first, right_last;  // the columns each side crosses
};

// One edge walked upwards from (x0, y0): its x at a height, and its slopes, both from one division
// while 1 / (dx dy) is finite; where dx dy is 0 or subnormal, one division each. dy/dx is infinite
// only for an edge too steep to cross a column's side (|dx| < 2^-1024 |dy|), where it is unused.
// dx/dy overflows only for an edge that rises less than 2^-1024 |dx|, and a quotient that large
// would make x0 + 0 * slope NaN at the bottom: clamped to the largest double, the slope keeps every
// x between the edge's ends, and so thin a band adds less than 2^-960 whatever its x.
struct RisingEdge {
  double x0, y0, dx_dy, dy_dx;
  RisingEdge(glm::dvec2 a, glm::dvec2 b) : x0(a.x), y0(a.y) {
    const double dx = b.x - a.x, dy = b.y - a.y, inverse = 1 / (dx * dy);
    if (std::isfinite(inverse)) [[likely]] {
      dx_dy = dx * dx * inverse;
      dy_dx = dy * dy * inverse;
    } else {
      dx_dy = dx / dy;
      dy_dx = dy / dx;
    }
    constexpr double largest = std::numeric_limits<double>::max();
    dx_dy = std::clamp(dx_dy, -largest, largest);
  }
  double x_at(double y) const { return x0 + (y - y0) * dx_dy; }
};

struct ByHeight {
  glm::dvec2 low, middle, high;
};

ByHeight sorted_by_height(const Triangle& t) {
  ByHeight v{t[0], t[1], t[2]};
  if (v.middle.y < v.low.y) std::swap(v.low, v.middle);
  if (v.high.y < v.middle.y) std::swap(v.middle, v.high);
  if (v.middle.y < v.low.y) std::swap(v.low, v.middle);
  return v;
}

// Which part of its pixel row a band is.
enum class Part { whole_row, below_middle, above_middle };

// [listing walk_bands]
// Calls visit(row, band, part) for every band of rows first_row..last_row, bottom to top. The
// vertices sorted by height, the long edge from the lowest to the highest is one side of the
// triangle, the two short edges through the middle vertex the other. Where a side leaves a row
// is where it enters the next, so each side's x and column are computed once per row boundary.
// The row that holds the middle vertex is two bands, below and above it, so that in every band
// each side is one straight piece. Always inlined, with visit, so that the AVX2 copy of the summed
// row loop (add_summed_rows below) compiles all of it for AVX2.
template <class Visit>
[[gnu::always_inline]] inline void walk_bands(const ByHeight& v, int first_row, int last_row,
                                              Visit&& visit) {
  const RisingEdge along(v.low, v.high), lower(v.low, v.middle), upper(v.middle, v.high);
  const glm::dvec2 to_high = v.high - v.low, to_middle = v.middle - v.low;
  const bool short_on_left = to_high.x * to_middle.y - to_high.y * to_middle.x > 0;
  struct Side {  // where a side crosses the current height
    const RisingEdge* edge;
    double x;
    int column;
    void move_to(double y) { set(edge->x_at(y)); }
    void set(double at) {
      x = at;
      column = column_of(at);
    }
  };
  double y0 = std::max(first_row - 0.5, v.low.y);
  const bool turned = y0 >= v.middle.y;  // past the middle vertex: the short side's upper edge
  const RisingEdge* short_edge = turned ? &upper : &lower;
  // The row where the short side turns (none if it has turned, or if the top is flat).
  const int middle_row = turned || v.middle.y == v.high.y ? INT_MIN : column_of(v.middle.y);
  Side left{short_on_left ? short_edge : &along, 0, 0};
  Side right{short_on_left ? &along : short_edge, 0, 0};
  left.move_to(y0);
  right.move_to(y0);
  Side& short_side = short_on_left ? left : right;
  const auto band_to = [&](int row, double y1, Part part) __attribute__((always_inline)) {
    const Side l0 = left, r0 = right;
    left.move_to(y1);
    right.move_to(y1);
    visit(row,
          Band{y0, y1, l0.x, left.x, r0.x, right.x, l0.edge->dy_dx, r0.edge->dy_dx,
               std::min(l0.column, left.column), std::max(l0.column, left.column),
               std::min(r0.column, right.column), std::max(r0.column, right.column)},
          part);
    y0 = y1;
  };
  for (int row = first_row; row <= last_row; ++row) {
    const double y1 = std::min(row + 0.5, v.high.y);
    Part part = Part::whole_row;
    if (row == middle_row) [[unlikely]] {  // the short side turns at the middle vertex
      if (v.middle.y > y0) {
        band_to(row, v.middle.y, Part::below_middle);
        part = Part::above_middle;
      }
      short_side.edge = &upper;
      short_side.set(v.middle.x);
    }
    band_to(row, y1, part);
  }
}
// [/listing]

// A band's two pieces into the cells, as the counter-clockwise outline walks them: up the right
// side, down the left side.
void add_band(RowCells& cells, const Band& b) {
  cells.add_segment(RowCells::Side::left, b.left1, b.y1, b.left0, b.y0, b.left_dy_dx);
  cells.add_segment(RowCells::Side::right, b.right0, b.y0, b.right1, b.y1, b.right_dy_dx);
}

// Sets every value from first up to end to 1, four floats per store, as chapter 08's fill_pixels
// fills a span: the last store ends exactly at end, overlapping the one before (equal values).
void store_ones(float* first, float* end) {
  using Four = ch08::Vector<float, 4>;
  const Four ones = Four{} + 1.0f;
  if (end - first < 4) {
    std::fill(first, end, 1.0f);
    return;
  }
  for (; first < end - 4; first += 4) std::memcpy(first, &ones, sizeof ones);
  std::memcpy(end - 4, &ones, sizeof ones);
}

// [listing add_band_directly]
// Composited over (step 5), most bands need no cells either. Walking the left piece's cells, then
// the pixels between the sides, then the right piece's cells, from left to right, the running
// cover is known at every pixel, so each pixel's coverage is written as soon as it is known. A
// side wholly off the canvas is not walked: left of it, its cover reaches column 0; right of it,
// the pixels between reach the last column. False, having written nothing, when a piece crosses
// the canvas's left or right edge, or when the sides share cells, where a pixel must receive its
// whole coverage at once. Put composites a coverage over a pixel; the pixels wholly inside a band
// of a whole row become 1 whatever they held, so they are stored, not blended.
template <class Put>
bool add_band_directly(float* row, int width, const Band& b, Put put) {
  bool walk_left = true, walk_right = true;
  if (b.left_first < 0 || b.right_last >= width) [[unlikely]] {  // the band reaches off the canvas
    if (b.right_last < 0 || b.left_first >= width) return true;  // wholly: nothing to add
    walk_left = b.left_first >= 0;      // else the left side must be on the canvas or wholly left,
    walk_right = b.right_last < width;  // and the right side on it or wholly right of it
    if (walk_left ? b.left_last >= width : b.left_last >= 0) return false;
    if (walk_right ? b.right_first < 0 : b.right_first < width) return false;
  }
  if (b.left_last >= b.right_first) return false;
  double inside = b.y1 - b.y0;  // right of the left side, the band's whole height is inside
  if (walk_left) {
    double cover = 0;  // the left piece runs down: negative heights, coverage -(cover + area)
    for_each_cell(b.left1, b.y1, b.left0, b.y0, b.left_dy_dx, b.left_first, b.left_last,
                  [&](int column, double area, double height) {
                    put(row[column], static_cast<float>(-(cover + area)));
                    cover += height;
                  });
    inside = -cover;
  }
  const float between = static_cast<float>(inside);
  float* const begin = row + (walk_left ? b.left_last + 1 : 0);
  float* const end = row + (walk_right ? b.right_first : width);
  if (between == 1.0f) {
    store_ones(begin, end);  // a whole pixel over any value v is v + (1 - v) = 1: no read
  } else {
    for (float* pixel = begin; pixel < end; ++pixel) put(*pixel, between);
  }
  if (walk_right) {
    double cover = 0;  // the right piece runs up: what lies right of it is outside
    for_each_cell(b.right0, b.y0, b.right1, b.y1, b.right_dy_dx, b.right_first, b.right_last,
                  [&](int column, double area, double height) {
                    put(row[column], static_cast<float>(inside - (cover + area)));
                    cover += height;
                  });
  }
  return true;
}
// [/listing]

// [listing right_of]
// A group of pixels at a time. In a band of height H, pixel i's coverage is H (P_left - P_right),
// where P of a side's piece is the part of the pixel right of it, averaged over the band: the mean
// of clamp(i + 1/2 - x, 0, 1) over the piece's x range [lo, lo + d] (a straight piece passes every
// x of its range for the same share of its height). Along the piece, g = i + 1/2 - x falls
// linearly from g0 = i + 1/2 - lo by d: it is at least 1 (the pixel wholly right of the piece)
// for the first fraction ta = (g0 - 1) / d of the way, at most 0 from tb = g0 / d on, and in
// between its mean is g0 - d (ta + tb) / 2. With both fractions clamped to [0, 1], P is right for
// any pixel of the row: 1 right of the piece, 0 left of it, no test of which cells the piece
// crosses. A vertical piece (d = 0) gets 1/d = 1e30: ta and tb are 0 or 1, P = clamp(g0, 0, 1).
// In floats, since g0 is small where it matters: within 1e-6 of the exact area. A group is four
// floats; the AVX2 copy of the row loop (below) adds eight at a time between the sides.
template <int Width>
using Lanes = ch08::Vector<float, Width>;
constexpr Lanes<4> centre_offsets = {0.5f, 1.5f, 2.5f, 3.5f};  // i + 1/2 from i = 0

inline Lanes<4> clamp01(Lanes<4> v) {
#if defined(__SSE__)
  return _mm_min_ps(_mm_max_ps(v, Lanes<4>{}), Lanes<4>{} + 1.0f);  // one instruction each
#else
  const Lanes<4> zero = {}, one = zero + 1.0f;
  v = v > zero ? v : zero;
  return v < one ? v : one;
#endif
}

struct PieceLanes {
  double lo;              // the piece's least x
  float inverse, half_d;  // 1 / d and d / 2
  PieceLanes(double x0, double x1)
      : lo(std::min(x0, x1)),
        inverse(1.0f / (static_cast<float>(std::abs(x1 - x0)) + 1e-30f)),
        half_d(static_cast<float>(std::abs(x1 - x0)) / 2) {}
  // P for pixels i .. i + 3.
  [[gnu::always_inline]] Lanes<4> right_of(int i) const {
    const Lanes<4> g0 = static_cast<float>(i - lo) + centre_offsets;
    const Lanes<4> ta = clamp01((g0 - 1.0f) * inverse), tb = clamp01(g0 * inverse);
    return ta + (tb - ta) * (g0 - half_d * (ta + tb));
  }
};
// [/listing]

template <class V>
[[gnu::always_inline]] inline void add_group(float* pixels, const V& values) {
  V v;
  std::memcpy(&v, pixels, sizeof v);
  v += values;
  std::memcpy(pixels, &v, sizeof v);
}

// Adds a group's values to the pixels from `first` on; at the canvas's right edge, only those on
// it.
template <int Width>
[[gnu::always_inline]] inline void add_lanes(float* row, int first, int width,
                                             const Lanes<Width>& values) {
  if (first + Width <= width) [[likely]]
    return add_group(row + first, values);
  float each[Width];  // copied here, so that only this rare path puts the group in memory
  std::memcpy(each, &values, sizeof each);
  for (int i = 0; first + i < width; ++i) row[first + i] += each[i];
}

// [listing add_run]
// Adds h to the count >= 4 values from first on, two groups of Width floats at a time. The last
// two groups (the first and the last group of a shorter run) are read before any group is written
// and written last, so they may overlap the groups before them, as chapter 08's fill_pixels ends
// a span with two overlapping stores: no pixels are left over, so no loop of smaller groups.
template <int Width>
[[gnu::always_inline]] inline void add_run(float* first, int count, float h) {
  if constexpr (Width > 4) {
    if (count < Width) return add_run<4>(first, count, h);
  }
  const Lanes<Width> add = Lanes<Width>{} + h;
  float* const last[2] = {first + std::max(count - 2 * Width, 0), first + count - Width};
  Lanes<Width> kept[2];  // their values before the run
  for (int k = 0; k < 2; ++k) std::memcpy(&kept[k], last[k], sizeof add);
  for (int i = 0; i < count - 2 * Width; i += 2 * Width) {
    add_group(first + i, add);
    add_group(first + i + Width, add);
  }
  for (int k = 0; k < 2; ++k) std::memcpy(last[k], &(kept[k] += add), sizeof add);
}
// [/listing]

// [listing add_band_lanes]
// A band summed onto the row four pixels at a time: a band within four pixels in one step;
// otherwise groups of four from the left piece's first column (or the canvas's) until past its
// last, then the run of pixels wholly inside, up to the right piece's first column, given H by
// add_run (groups of eight in the AVX2 copy of the row loop, four in the portable one), then
// groups of four from there until past the right piece's last column (or the canvas's). A run
// shorter than four pixels is left to the right piece's groups. Only the run takes groups of
// eight: each pixel gets the same bits from both copies (the playground's WebAssembly has only
// the portable one and draws what raster draws). A pixel that a group passes outside the triangle
// gets exactly 0. The band's numbers come as arguments, so that they stay in registers.
template <int Width>
[[gnu::always_inline]] inline void add_band_lanes(float* row, int width, double y0, double y1,
                                                  double left0, double left1, double right0,
                                                  double right1, int left_first, int left_last,
                                                  int right_first, int right_last) {
  if (right_last < 0 || left_first >= width) return;  // wholly off the canvas
  const PieceLanes left(left0, left1), right(right0, right1);
  const auto height = static_cast<float>(y1 - y0);
  int column = std::max(left_first, 0);
  if (right_last < column + 4 && column + 4 <= width) {  // the whole band in one group
    return add_group(row + column, height * (left.right_of(column) - right.right_of(column)));
  }
  left_last = std::min(left_last, width - 1);
  // Left of the right piece's first column, P_right is 0; right of the left piece, P_left is 1.
  for (; column <= left_last && column + 4 <= right_first; column += 4) {
    add_lanes<4>(row, column, width, height * left.right_of(column));
  }
  for (; column <= left_last; column += 4) {
    add_lanes<4>(row, column, width, height * (left.right_of(column) - right.right_of(column)));
  }
  const int inside_end = std::min(right_first, width);  // the pixels wholly inside end here
  if (inside_end - column >= 4) {
    add_run<Width>(row + column, inside_end - column, height);
    column = inside_end;
  }
  const int last = std::min(right_last, width - 1);
  for (; column <= last; column += 4) {
    add_lanes<4>(row, column, width, height * (1.0f - right.right_of(column)));
  }
}
// [/listing]

// [listing add_summed_rows]
// The summed blend's row loop: every band of the triangle's rows onto the canvas, a group of
// Width pixels at a time (the bands of a row add up).
template <int Width>
[[gnu::always_inline]] inline void add_summed_rows_in(CoverageCanvas& canvas, const ByHeight& v,
                                                      int first_row, int last_row) {
  const int width = canvas.width();
  // Inlined, so that the AVX2 copy compiles the bands' groups for AVX2 too.
  walk_bands(
      v, first_row, last_row, [&](int row, const Band& band, Part) __attribute__((always_inline)) {
        add_band_lanes<Width>(canvas.row(row), width, band.y0, band.y1, band.left0, band.left1,
                              band.right0, band.right1, band.left_first, band.left_last,
                              band.right_first, band.right_last);
      });
}

// The row loop in the copy for Set (ch08::copy_for): groups of four floats in the portable copy,
// eight in the AVX2 one. Elsewhere than x86-64 (the playground's WebAssembly) only the portable.
template <ch08::InstructionSet Set>
struct SummedRows {
  // The vertices by value: a local copy that no pixel store can alias stays in registers.
  [[gnu::always_inline]] static void run(CoverageCanvas& canvas, ByHeight v, int first_row,
                                         int last_row) {
    constexpr int floats = ch08::register_bytes(Set) / static_cast<int>(sizeof(float));
    add_summed_rows_in<floats>(canvas, v, first_row, last_row);
  }
};
// [/listing]

}  // namespace

int area_lane_floats(ch08::InstructionSet set) noexcept {
  return ch08::register_bytes(set) / static_cast<int>(sizeof(float));
}

namespace {

// [listing add_rows]
// Composited, a pixel takes its coverage at once: through the cells where the sides meet and in
// the row of the middle vertex.
template <class Put>
void add_rows_over(CoverageCanvas& canvas, const ByHeight& v, RowCells& cells, int first_row,
                   int last_row, Put put) {
  bool cells_started = false;
  walk_bands(v, first_row, last_row, [&](int row, const Band& band, Part part) {
    if (part == Part::whole_row && add_band_directly(canvas.row(row), canvas.width(), band, put)) {
      return;
    }
    if (!cells_started) cells.start_row(canvas.width());  // once per triangle, if at all
    cells_started = true;
    add_band(cells, band);
    if (part != Part::below_middle) cells.add_to_canvas(canvas, row, Blend::over);
  });
}
// [/listing]

// Twice the signed area: zero for a degenerate triangle.
double doubled_area(const Triangle& t) {
  return (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[2].x - t[0].x) * (t[1].y - t[0].y);
}

// Nothing to draw: a vertex NaN, infinite or beyond ±2^30, as validate_triangle refuses (within
// ±2^30 every row and column fits an int), or zero area.
bool adds_nothing(const Triangle& t) {
  for (const glm::dvec2& v : t) {  // false for NaN too
    if (!(std::abs(v.x) <= max_scene_coordinate && std::abs(v.y) <= max_scene_coordinate)) {
      return true;
    }
  }
  return doubled_area(t) == 0;
}

}  // namespace

void add_edges_in_row(RowCells& cells, const Triangle& triangle, int row) {
  if (adds_nothing(triangle)) return;
  const ByHeight v = sorted_by_height(triangle);
  if (row < column_of(v.low.y) || row - 0.5 >= v.high.y) return;  // no band of the row inside
  walk_bands(v, row, row, [&](int, const Band& band, Part) { add_band(cells, band); });
}

namespace {

// [listing draw_triangle_area]
// Calls add_rows(sorted, first_row, last_row) with the triangle's vertices sorted by height and
// the canvas rows it reaches, if any; a triangle that adds nothing reaches none.
template <class AddRows>
void with_rows(const CoverageCanvas& canvas, const Triangle& triangle, AddRows add_rows) {
  if (adds_nothing(triangle)) return;
  const ByHeight sorted = sorted_by_height(triangle);
  const int first_row = std::max(0, column_of(sorted.low.y));
  int last_row = column_of(sorted.high.y);
  if (last_row - 0.5 >= sorted.high.y) --last_row;  // a row that the top only touches
  last_row = std::min(canvas.height() - 1, last_row);
  if (first_row <= last_row) add_rows(sorted, first_row, last_row);
}

}  // namespace

void draw_triangle_area(CoverageCanvas& canvas, const Triangle& triangle, RowCells& cells,
                        Blend blend, ch08::InstructionSet set) {
  with_rows(canvas, triangle, [&](const ByHeight& sorted, int first_row, int last_row) {
    // One loop per blend, so the rows do not decide the blend at every pixel.
    if (blend == Blend::sum) {
      ch08::copy_for<SummedRows>(set)(canvas, sorted, first_row, last_row);
    } else {
      add_rows_over(canvas, sorted, cells, first_row, last_row,
                    [](float& v, float c) { v += c * (1.0f - v); });
    }
  });
}
// [/listing]

void draw_triangle_area_over(CoverageCanvas& canvas, const Triangle& triangle, RowCells& cells) {
  draw_triangle_area(canvas, triangle, cells, Blend::over);
}

}  // namespace tri::ch09
