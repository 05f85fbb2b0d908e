/// @file
/// Step 3 · span traversal: per row, the first and last covered pixel follow exactly from the
/// three edges, and the pixels between them are filled without any per-pixel test.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "chapters/08_fast_exact/instruction_sets.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/triangle_setup.hpp"
#include "common/canvas.hpp"
#include "common/color.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri::ch08 {

/// The covered pixels first..last (inclusive) of one row; empty when first > last.
struct RowSpan {
  int first;
  int last;
  bool empty() const noexcept { return first > last; }
  friend bool operator==(const RowSpan&, const RowSpan&) = default;
};

// [listing floor_div]
/// floor(a / b) for b > 0 and any sign of a (C++ division truncates toward zero instead).
constexpr std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
  const std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
// [/listing]

/// The covered pixels of row y (within the setup's range), computed directly: each edge is
/// w(dx) = w_row + step_x * dx >= 0, so an edge whose value grows to the right allows
/// dx >= ceil(-w_row / step_x) = -floor(w_row / step_x), one whose value shrinks allows
/// dx <= floor(w_row / -step_x), and a horizontal one (step_x == 0) allows all or nothing. Three
/// divisions per row: the reference the walker is tested against. Empty for an empty row.
RowSpan row_span(const TriangleSetup& setup, int y) noexcept;

// [listing span_walker]
/// The spans of successive rows, bottom to top, without any division per row. For each sloped
/// edge it keeps q = floor(w_row / s) (s = |step_x|) and the remainder w_row - s * q in [0, s);
/// a row adds step_y = dq * s + dr to w_row, so q grows by dq, the remainder by dr, and by one
/// more when the remainder reaches s. Exact, like Bresenham's error term.
///
/// An edge whose value grows to the right bounds a span from the left (first = -q), one shrinking
/// bounds it from the right (last = q). The three steps in x sum to zero (they are the vertex
/// height differences around the triangle), so one edge grows and one shrinks, and the third goes
/// either way: it and the edge on its side meet at the middle vertex, one bounds the rows below
/// that vertex and the other the rows above. So the walker keeps two bounds, and at the middle
/// vertex's row hands one side over to the edge above it (computed in the setup): two updates per
/// row, not three. A horizontal edge (step_x == 0) bounds rows instead of pixels, so it only
/// narrows the rows walked.
class SpanWalker {
 public:
  explicit SpanWalker(const TriangleSetup& setup) noexcept;

  /// The rows where a span can be non-empty: every horizontal edge passes there. The range's
  /// other rows are empty. first_row() > last_row() when there is none.
  int first_row() const noexcept { return first_row_; }
  int last_row() const noexcept { return last_row_; }

  /// The span of the current row (starting with first_row()).
  RowSpan span() const noexcept { return span_between(left_, right_); }

  /// Moves to the next row up.
  void next_row() noexcept {
    left_.next_row();
    right_.next_row();
    if (++row_ == middle_row_) [[unlikely]] {
      if (above_from_left_) {
        left_ = above_;
      } else {
        right_ = above_;
      }
    }
  }

  /// Calls visit(y, span) for the current row and every row above it up to last_row(), in order,
  /// as span() and next_row() would, without changing the walker. The loop the fills use: one
  /// loop below the middle vertex and one above it, with their two bounds in local variables, so
  /// they stay in registers (a hand-over inside one loop kept them in memory).
  template <class Visit>
  [[gnu::always_inline]] inline void for_each_row(Visit&& visit) const {
    Bound left = left_, right = right_;
    const auto walk = [&](int y, int end) {
      for (; y < end; ++y, left.next_row(), right.next_row()) visit(y, span_between(left, right));
    };
    const int end = last_row_ + 1;
    if (middle_row_ > row_ && middle_row_ < end) {
      walk(row_, middle_row_);
      if (above_from_left_) {
        left = above_;
      } else {
        right = above_;
      }
      walk(middle_row_, end);
    } else {
      walk(row_, end);
    }
  }

 private:
  struct Bound {
    std::int64_t quotient;   // floor(w_row / s)
    std::int64_t remainder;  // w_row - s * quotient, in [0, s)
    std::int64_t divisor;    // s = |step_x|
    std::int64_t quotient_step;
    std::int64_t remainder_step;

    [[gnu::always_inline]] void next_row() noexcept {
      quotient += quotient_step;
      remainder += remainder_step;
      // Branch-free carry: the remainder stays in [0, divisor).
      const bool carry = remainder >= divisor;
      quotient += carry;
      remainder -= carry ? divisor : 0;
    }
  };
  RowSpan span_between(const Bound& left, const Bound& right) const noexcept {
    const std::int64_t first = std::max(std::int64_t{0}, -left.quotient);
    const std::int64_t last = std::min(last_dx_, right.quotient);
    if (first > last) return {first_x_, first_x_ - 1};
    return {first_x_ + static_cast<int>(first), first_x_ + static_cast<int>(last)};
  }

  Bound left_;   // the edge that bounds the current row from the left
  Bound right_;  // ... from the right
  Bound above_;  // the edge that takes over one side at middle_row_
  bool above_from_left_;
  int row_;         // the current row
  int middle_row_;  // where above_ takes over; beyond every row when it does not
  int first_x_;
  std::int64_t last_dx_;
  int first_row_;
  int last_row_;
};
// [/listing]

/// The bytes of each store with which fill_spans fills a span of RowWriter in the copy for `set`:
/// 32 with AVX2, else 16 (SSE2, the portable build's); by default the copy the host runs.
int span_store_bytes(InstructionSet set = widest_instruction_set()) noexcept;

// [listing fill_rows]
/// The span fill's loop, one copy per instruction set: each row's span goes to the writer's rows
/// (its row-store hook), which move up a row at a time, so nothing is asked for by y per row.
template <class Writer>
struct SpanFill {
  template <InstructionSet Set>
  struct Loop {
    [[gnu::always_inline]] static void run(const TriangleSetup& setup, Writer& writer) {
      const SpanWalker walker(setup);
      if (walker.first_row() > walker.last_row()) return;
      auto rows = writer.template rows_from<Set>(walker.first_row());
      walker.for_each_row([&](int y, RowSpan s) {
        if (!s.empty()) rows.fill(y, s.first, s.last + 1);
        rows.next_row();
      });
    }
  };
};

/// Draws a prepared triangle the way draw_triangle_spans does, through any writer, with the copy
/// of the loop for `set` (by default the widest the host runs). Through RowWriter, each span is
/// one fill_pixels_in with the stores of span_store_bytes(set); a writer whose rows store alike
/// in every copy takes the portable one.
template <PixelWriter Writer>
void fill_spans(const TriangleSetup& setup, Writer& writer,
                InstructionSet set = widest_instruction_set()) {
  if constexpr (same_rows_in_every_copy<Writer>) {
    SpanFill<Writer>::template Loop<InstructionSet::portable>::run(setup, writer);
  } else {
    copy_for<SpanFill<Writer>::template Loop>(set)(setup, writer);
  }
}
// [/listing]

/// Step 3 · span traversal: one filled span per row from SpanWalker, through either canvas writer;
/// a sliver costs its rows, not its bounding box. On the canvas (compiled in spans.cpp):
/// draw_triangle_spans for one triangle, OnCanvas' draw_rows for rows first_row..last_row of it.
void fill_spans(const TriangleSetup& setup, CanvasWriter writer);
extern template struct OnCanvas<fill_spans>;
inline constexpr DrawTriangleFunction draw_triangle_spans = OnCanvas<fill_spans>::draw;

}  // namespace tri::ch08
