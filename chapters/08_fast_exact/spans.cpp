#include "chapters/08_fast_exact/spans.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace tri::ch08 {

// [listing row_span]
RowSpan row_span(const TriangleSetup& setup, int y) noexcept {
  const ch05::PixelBox& r = setup.range;
  if (y < r.min.y || y > r.max.y) return {r.min.x, r.min.x - 1};
  std::int64_t first = 0, last = r.max.x - r.min.x;
  for (const EdgeFunction& edge : setup.edges) {
    const std::int64_t w = edge.at(0, y - r.min.y);
    if (edge.step_x > 0) {
      first = std::max(first, -floor_div(w, edge.step_x));
    } else if (edge.step_x < 0) {
      last = std::min(last, floor_div(w, -edge.step_x));
    } else if (w < 0) {
      last = -1;
    }
  }
  if (first > last) return {r.min.x, r.min.x - 1};
  return {r.min.x + static_cast<int>(first), r.min.x + static_cast<int>(last)};
}
// [/listing]

namespace {

// Beyond any pixel offset of a canvas: a right bound that never binds. A left bound of quotient
// 0 and no steps allows first >= 0: it never binds either.
constexpr std::int64_t never_binding_right = std::int64_t{1} << 62;

}  // namespace

SpanWalker::SpanWalker(const TriangleSetup& setup) noexcept
    : left_{0, 0, 1, 0, 0},
      right_{never_binding_right, 0, 1, 0, 0},
      above_{},
      above_from_left_(true),
      row_(setup.range.min.y),
      middle_row_(std::numeric_limits<int>::max()),
      first_x_(setup.range.min.x),
      last_dx_(setup.range.max.x - setup.range.min.x) {
  const ch05::PixelBox& r = setup.range;
  // Rows (offsets from first_y) where every horizontal edge passes: w + step_y * k >= 0.
  std::int64_t first_k = 0, last_k = r.max.y - r.min.y;
  for (const EdgeFunction& e : setup.edges) {
    if (e.step_x != 0) continue;
    if (e.step_y > 0) {
      first_k = std::max(first_k, -floor_div(e.value, e.step_y));
    } else if (e.step_y < 0) {
      last_k = std::min(last_k, floor_div(e.value, -e.step_y));
    } else if (e.value < 0) {
      last_k = -1;
    }
  }
  if (first_k > last_k) {
    first_row_ = r.min.y;
    last_row_ = r.min.y - 1;
    return;
  }
  first_row_ = r.min.y + static_cast<int>(first_k);
  last_row_ = r.min.y + static_cast<int>(last_k);
  row_ = first_row_;
  // [listing span_walker_split]
  // Row y's pixel centres lie at 256 y on the grid. Two sloped edges on one side meet at the
  // vertex with the middle y (the third edge spans all rows): below it (256 y < middle_y, that is
  // y < ceil(middle_y / 256)) the upper edge's line lies outside the lower edge's half-plane, so
  // only the lower edge can bound; above it only the upper edge can; on its row (256 y ==
  // middle_y) both give the same bound, having the same tie rule (both left or both right).
  const std::int64_t middle_row =
      (setup.middle_y >> subpixel_bits) + ((setup.middle_y & ((1 << subpixel_bits) - 1)) != 0);
  const std::int64_t middle_k = std::clamp(middle_row - r.min.y, first_k, last_k + 1);
  const auto bound_at = [&](const EdgeFunction& e, std::int64_t k) {
    const std::int64_t w = e.at(0, k);
    const std::int64_t s = e.step_x > 0 ? e.step_x : -e.step_x;
    const std::int64_t q = floor_div(w, s);
    const std::int64_t dq = floor_div(e.step_y, s);
    return Bound{q, w - s * q, s, dq, e.step_y - s * dq};
  };
  for (std::size_t i = 0; i < 3; ++i) {
    const EdgeFunction& e = setup.edges[i];
    if (e.step_x == 0) continue;
    const bool from_left = e.step_x > 0;
    // Two edges on one side follow each other around the triangle (counter-clockwise), meeting
    // at the middle vertex: the first ends there. Left edges run down, so there the first is
    // the upper one; right edges run up, so there the first is the lower one.
    const EdgeFunction& next = setup.edges[(i + 1) % 3];
    const EdgeFunction& previous = setup.edges[(i + 2) % 3];
    const bool same_side_next = next.step_x != 0 && (next.step_x > 0) == from_left;
    const bool same_side_previous = previous.step_x != 0 && (previous.step_x > 0) == from_left;
    const bool above = (same_side_next && from_left) || (same_side_previous && !from_left);
    const bool below = (same_side_next && !from_left) || (same_side_previous && from_left);
    Bound& side = from_left ? left_ : right_;
    if (above && middle_k > first_k) {
      if (middle_k <= last_k) {
        above_ = bound_at(e, middle_k);
        above_from_left_ = from_left;
        middle_row_ = r.min.y + static_cast<int>(middle_k);
      }
    } else if (!below || middle_k > first_k) {
      side = bound_at(e, first_k);
    }
  }
  // [/listing]
}

int span_store_bytes(InstructionSet set) noexcept {
  return register_bytes(set);
}

void fill_spans(const TriangleSetup& setup, CanvasWriter any_writer) {
  any_writer.visit([&](auto& writer) { fill_spans(setup, writer); });
}

template struct OnCanvas<fill_spans>;

}  // namespace tri::ch08
