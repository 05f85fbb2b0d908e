#include "chapters/08_fast_exact/batched.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "chapters/08_fast_exact/hybrid.hpp"
#include "chapters/08_fast_exact/instruction_sets.hpp"
#include "chapters/08_fast_exact/narrow_canvases.hpp"
#include "chapters/08_fast_exact/pixel_writers.hpp"
#include "chapters/08_fast_exact/spans.hpp"
#include "chapters/08_fast_exact/tiled.hpp"

// The lane functions take and return vectors by value, and AVX2's are 32 bytes wide. GCC and
// Clang note (-Wpsabi) that such a call passes them differently with and without AVX; these
// functions have internal linkage and are always inlined, so no such call exists. For the whole
// file: GCC gives the note after its end, past any pragma that would restore it.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace tri::ch08 {
namespace {

// The lanes are generic vectors (instruction_sets.hpp), as in step 5, here exactly one register
// wide: two doubles in the portable copy (SSE2, every x86-64), four in the AVX2 copy. Wider
// generic vectors than the target's registers were split badly: GCC 12 turned their comparisons
// into one scalar comparison per lane. Every function below is a template over the register
// (Lanes) and always inlined, so that it is compiled for the instructions of the copy that calls
// it. Comparisons give Integers: all bits set where true.
template <class Lanes>
using IntegersOf = decltype(Lanes{} < Lanes{});
template <class Lanes>
constexpr std::size_t lanes_in = sizeof(Lanes) / sizeof(double);

#define LANE_FUNCTION [[gnu::always_inline]] inline

template <class Lanes>
LANE_FUNCTION Lanes all(double x) noexcept {
  return Lanes{} + x;
}

// 1.0 where the mask is set and 0.0 elsewhere: the mask's bits over those of 1.0.
template <class Lanes>
LANE_FUNCTION Lanes ones_where(IntegersOf<Lanes> mask) noexcept {
  return (Lanes)(mask & (IntegersOf<Lanes>)all<Lanes>(1.0));
}

// Written as a comparison and a choice, which GCC compiles to one minpd or maxpd.
template <class Lanes>
LANE_FUNCTION Lanes min(Lanes a, Lanes b) noexcept {
  return a < b ? a : b;
}
template <class Lanes>
LANE_FUNCTION Lanes max(Lanes a, Lanes b) noexcept {
  return a < b ? b : a;
}

// [listing lane_rounding]
// SSE2 has no rounding instruction for doubles. Adding 1.5 * 2^52 to any |x| < 2^51 leaves no
// bit for a fraction, so the sum is rounded to an integer: the nearest one, ties to even (the
// default rounding mode). Subtracting it again gives that integer as a double.
constexpr double round_magic = 6755399441055744.0;

template <class Lanes>
LANE_FUNCTION Lanes nearest_even(Lanes x) noexcept {
  return (x + round_magic) - round_magic;
}

// floor(x): one less where rounding went up.
template <class Lanes>
LANE_FUNCTION Lanes floor_lanes(Lanes x) noexcept {
  const Lanes r = nearest_even(x);
  return r - ones_where<Lanes>(r > x);
}

// snap_to_256ths in lanes, for |p| <= 2^16: p * 256 rounded to the nearest integer, halves up.
// x - r is exact (r is the integer nearest x), and it is 0.5 only for a half that went down.
template <class Lanes>
LANE_FUNCTION Lanes snap(Lanes p) noexcept {
  const Lanes x = p * 256.0;
  const Lanes r = nearest_even(x);
  return r + ones_where<Lanes>(x - r >= 0.5);
}

// A whole number |x| < 2^51 as a 64-bit integer, without a conversion instruction (SSE2 has none
// for 64 bits): x + 1.5 * 2^52 holds x in the low bits of its significand.
template <class Lanes>
LANE_FUNCTION IntegersOf<Lanes> to_integers(Lanes x) noexcept {
  using Integers = IntegersOf<Lanes>;
  return (Integers)(x + round_magic) - (Integers)all<Lanes>(round_magic);
}
// [/listing]

// [listing lane_edge]
template <class Lanes>
struct EdgeLanes {
  Lanes value, step_x, step_y;
};

// make_edge in lanes: the edge a -> b at the origin pixel (px, py, in 1/256 pixel). Every
// product and difference is an integer below 2^51, so exact in doubles; dividing by 256 too.
template <class Lanes>
LANE_FUNCTION EdgeLanes<Lanes> edge_lanes(Lanes ax, Lanes ay, Lanes bx, Lanes by, Lanes px,
                                          Lanes py) noexcept {
  const Lanes e = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  const Lanes quotient = e * (1.0 / 256);
  const Lanes value = floor_lanes(quotient);
  // The top-left bias: minus one for an edge that is not top-left where e is a multiple of 256.
  const IntegersOf<Lanes> top_left = ((ay == by) & (bx < ax)) | (by < ay);
  return {value - ones_where<Lanes>((value == quotient) & ~top_left), ay - by, bx - ax};
}
// [/listing]

// Stores one register of lanes into lanes first.. of a field of SetupLanes.
template <class Integers>
LANE_FUNCTION void store(Integers values, std::array<std::int64_t, setup_lanes>& field,
                         std::size_t first) {
  std::memcpy(field.data() + first, &values, sizeof values);
}

// The vertices of setup_lanes triangles, one array per coordinate (x0, y0, x1, y1, x2, y2).
using Vertices = std::array<std::array<double, setup_lanes>, 6>;

// [listing set_up_register]
// set_up_lanes for the lanes first.. of one register.
template <class Lanes>
LANE_FUNCTION void set_up_register(const Vertices& vertices, std::size_t first, int width,
                                   int height, SetupLanes& lanes) noexcept {
  using Integers = IntegersOf<Lanes>;
  Lanes x[3], y[3];
  for (std::size_t v = 0; v < 3; ++v) {
    std::memcpy(&x[v], vertices[2 * v].data() + first, sizeof(Lanes));
    std::memcpy(&y[v], vertices[2 * v + 1].data() + first, sizeof(Lanes));
  }
  // Doubles are exact only for integers below 2^53, which bounds the coordinates: a lane with a
  // vertex beyond ±2^16 pixels goes to the scalar setup_triangle. Its vertices are zeroed here,
  // so every number the lanes form stays in range. A multiplication by 1 or 0, since GCC 12
  // compiled the mask's bits over theirs into a scalar choice per lane for SSE2.
  const Lanes highest = max(max(max(x[0], y[0]), max(x[1], y[1])), max(x[2], y[2]));
  const Lanes lowest = min(min(min(x[0], y[0]), min(x[1], y[1])), min(x[2], y[2]));
  const Integers near = (highest <= max_lane_coordinate) & (lowest >= -max_lane_coordinate);
  for (std::size_t v = 0; v < 3; ++v) {
    x[v] = snap(x[v] * ones_where<Lanes>(near));
    y[v] = snap(y[v] * ones_where<Lanes>(near));
  }
  // Candidate pixels: centres within the snapped extent (ceil and floor of 1/256 units), clipped.
  const Lanes min_x = min(min(x[0], x[1]), x[2]), max_x = max(max(x[0], x[1]), x[2]);
  const Lanes min_y = min(min(y[0], y[1]), y[2]), max_y = max(max(y[0], y[1]), y[2]);
  const Lanes x0 = max(-floor_lanes(min_x * (-1.0 / 256)), Lanes{});
  const Lanes y0 = max(-floor_lanes(min_y * (-1.0 / 256)), Lanes{});
  const Lanes x1 = min(floor_lanes(max_x * (1.0 / 256)), all<Lanes>(width - 1));
  const Lanes y1 = min(floor_lanes(max_y * (1.0 / 256)), all<Lanes>(height - 1));
  // Twice the signed area: zero covers nothing, negative is clockwise and gets turned around.
  const Lanes area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  const Lanes bx = area < 0 ? x[2] : x[1], by = area < 0 ? y[2] : y[1];
  const Lanes cx = area < 0 ? x[1] : x[2], cy = area < 0 ? y[1] : y[2];
  const Lanes px = x0 * 256.0, py = y0 * 256.0;
  const EdgeLanes<Lanes> edges[3] = {edge_lanes(bx, by, cx, cy, px, py),
                                     edge_lanes(cx, cy, x[0], y[0], px, py),
                                     edge_lanes(x[0], y[0], bx, by, px, py)};
  for (std::size_t e = 0; e < 3; ++e) {
    store(to_integers(edges[e].value), lanes.value[e], first);
    store(to_integers(edges[e].step_x), lanes.step_x[e], first);
    store(to_integers(edges[e].step_y), lanes.step_y[e], first);
  }
  store(to_integers(x0), lanes.min_x, first);
  store(to_integers(y0), lanes.min_y, first);
  store(to_integers(x1), lanes.max_x, first);
  store(to_integers(y1), lanes.max_y, first);
  store(to_integers(max(max_x - min_x, max_y - min_y)), lanes.vertex_extent, first);
  store(to_integers(max(min(y[0], y[1]), min(max(y[0], y[1]), y[2]))), lanes.middle_y, first);
  const Integers drawn = (x0 <= x1) & (y0 <= y1) & (area != 0);
  const Integers result = (~near & 2) | (near & drawn & 1);  // LaneResult's numbers
  for (std::size_t i = 0; i < lanes_in<Lanes>; ++i) {
    lanes.result[first + i] = static_cast<LaneResult>(result[i]);
  }
}
// [/listing]

template <class Lanes>
LANE_FUNCTION void set_up_registers(const Vertices& vertices, int width, int height,
                                    SetupLanes& lanes) noexcept {
  for (std::size_t first = 0; first < setup_lanes; first += lanes_in<Lanes>) {
    set_up_register<Lanes>(vertices, first, width, height, lanes);
  }
}

// set_up_registers in the copy for Set: SSE2's two lanes per instruction, or AVX2's four with
// three operands (no copies).
template <InstructionSet Set>
struct SetUpRegisters {
  [[gnu::always_inline]] static void run(const Vertices& vertices, int width, int height,
                                         SetupLanes& lanes) noexcept {
    set_up_registers<Register<double, Set>>(vertices, width, height, lanes);
  }
};

#undef LANE_FUNCTION

}  // namespace

// [listing set_up_lanes]
void set_up_lanes(std::span<const SceneTriangle> triangles, int width, int height,
                  SetupLanes& lanes, InstructionSet set) noexcept {
  // The vertices as a structure of arrays. Lanes past the triangles given keep zeros: zero area.
  Vertices vertices{};
  const std::size_t count = std::min<std::size_t>(triangles.size(), setup_lanes);
  for (std::size_t i = 0; i < count; ++i) {
    for (std::size_t v = 0; v < 3; ++v) {
      vertices[2 * v][i] = triangles[i].vertices[v].x;
      vertices[2 * v + 1][i] = triangles[i].vertices[v].y;
    }
  }
  copy_for<SetUpRegisters>(set)(vertices, width, height, lanes);
}
// [/listing]

// [listing draw_group]
template <PixelWriter Writer>
void draw_group(Canvas& canvas, std::span<const SceneTriangle> group, int row_end,
                SetupLanes& lanes, InstructionSet set) {
  for_each_group_setup(group, canvas.width(), canvas.height(), lanes, set,
                       [&](std::size_t i, const TriangleSetup& setup) {
                         Writer writer(canvas, group[i].color, row_end);
                         fill_hybrid(setup, writer);
                       });
}
// [/listing]

template void draw_group<RowWriter>(Canvas&, std::span<const SceneTriangle>, int, SetupLanes&,
                                    InstructionSet);
template void draw_group<CountingWriter>(Canvas&, std::span<const SceneTriangle>, int, SetupLanes&,
                                         InstructionSet);

namespace {

// [listing draw_groups]
template <PixelWriter Writer>
void draw_groups(Canvas& canvas, std::span<const SceneTriangle> triangles, InstructionSet set) {
  SetupLanes lanes;
  while (!triangles.empty()) {
    const std::size_t count = std::min<std::size_t>(triangles.size(), setup_lanes);
    draw_group<Writer>(canvas, triangles.first(count), canvas.width(), lanes, set);
    triangles = triangles.subspan(count);
  }
}
// [/listing]

}  // namespace

void draw_triangle_batched(Canvas& canvas, const Triangle& triangle, Color color) {
  const SceneTriangle one{triangle, color};
  draw_batch_batched(canvas, std::span(&one, 1));
}

void draw_batch_batched(Canvas& canvas, std::span<const SceneTriangle> triangles) {
  // On a canvas far larger than the caches, step 9's tiles on this thread: a tile stays cached
  // while all its triangles are drawn, instead of every triangle going through memory.
  if (std::int64_t{canvas.width()} * canvas.height() > tiled_canvas_pixels &&
      triangles.size() >= tiled_batch_triangles) {
    TileBins bins;
    bins.start(triangles, canvas.width(), canvas.height());
    for (int chunk = 0; chunk < bins.chunks(); ++chunk) bins.bin_chunk(chunk);
    for (int tile = 0; tile < bins.grid().count(); ++tile) bins.draw_tile(canvas, tile);
    return;
  }
  draw_batch_batched_with(canvas, triangles, widest_instruction_set());
}

void draw_narrow_batched(NarrowTarget& target, std::span<const SceneTriangle> triangles) {
  draw_narrow_batched_with(target, triangles, widest_instruction_set());
}

// [listing draw_narrow_batched]
void draw_narrow_batched_with(NarrowTarget& target, std::span<const SceneTriangle> triangles,
                              InstructionSet set) {
  SetupLanes lanes;
  for (std::size_t first = 0; first < triangles.size(); first += setup_lanes) {
    const auto group = triangles.subspan(first).first(
        std::min<std::size_t>(triangles.size() - first, setup_lanes));
    for_each_group_setup(group, target.width(), target.height(), lanes, set,
                         [&](std::size_t i, const TriangleSetup& setup) {
                           // A narrow triangle goes to the mask row by row in lanes.
                           if (target.mask != nullptr && fits_mask_lanes(setup)) {
                             fill_mask_lanes(*target.mask, setup, set);
                             return;
                           }
                           target.with_writer(first + i,
                                              [&](auto& writer) { fill_spans(setup, writer); });
                         });
  }
}
// [/listing]

void draw_batch_batched_with(Canvas& canvas, std::span<const SceneTriangle> triangles,
                             InstructionSet set) {
  with_writer_type(canvas, [&]<class Writer>() { draw_groups<Writer>(canvas, triangles, set); });
}

}  // namespace tri::ch08
