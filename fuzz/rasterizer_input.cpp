#include "fuzz/rasterizer_input.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <limits>

namespace tri::fuzz {
namespace {

// Reads bytes front to back; past the end every byte is zero, so any input decodes.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  bool at_end() const noexcept { return next_ >= bytes_.size(); }

  std::uint8_t byte() noexcept {
    const std::uint8_t value = next_ < bytes_.size() ? bytes_[next_] : std::uint8_t{0};
    ++next_;
    return value;
  }

  // Little-endian on every host, so a corpus file means the same everywhere.
  double raw_double() noexcept {
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= std::uint64_t{byte()} << (8 * i);
    return std::bit_cast<double>(bits);
  }

 private:
  std::span<const std::uint8_t> bytes_;
  std::size_t next_ = 0;
};

constexpr std::size_t coordinates_per_triangle = 6;

int canvas_side(std::uint8_t byte) noexcept {
  return byte % max_fuzz_canvas_side + 1;
}

SceneTriangle read_triangle(ByteReader& in) {
  const bool interesting = in.byte() % 2 == 1;
  SceneTriangle t;
  t.color.r = in.byte();
  t.color.g = in.byte();
  t.color.b = in.byte();
  t.color.a = 255;
  std::array<double, coordinates_per_triangle> c{};
  for (double& value : c) {
    if (interesting) {
      const auto base = static_cast<Base>(in.byte() % static_cast<int>(Base::count));
      const auto whole = static_cast<std::int8_t>(in.byte());
      value = interesting_value({base, whole, in.byte()});
    } else {
      value = in.raw_double();
    }
  }
  t.vertices = {glm::dvec2(c[0], c[1]), glm::dvec2(c[2], c[3]), glm::dvec2(c[4], c[5])};
  return t;
}

void append_color(std::vector<std::uint8_t>& bytes, Color color) {
  bytes.insert(bytes.end(), {color.r, color.g, color.b});
}

}  // namespace

double base_value(Base base) noexcept {
  // One value per base, in the enum's order; Base::count (not a base) falls outside and reads 0.
  constexpr double inf = std::numeric_limits<double>::infinity();
  constexpr double largest = std::numeric_limits<double>::max();
  constexpr std::array<double, static_cast<std::size_t>(Base::count)> values{
      0.0,                                       // zero
      max_scene_coordinate,                      // limit
      -max_scene_coordinate,                     // minus_limit
      1e7,                                       // ten_million
      -1e7,                                      // minus_ten_million
      16777217.0,                                // float_gap
      -16777217.0,                               // minus_float_gap
      536870912.0,                               // half_limit
      -536870912.0,                              // minus_half_limit
      2147483648.0,                              // beyond_int
      max_fuzz_canvas_side,                      // canvas_edge
      0.49999999999999994,                       // almost_half
      1e-310,                                    // subnormal
      largest,                                   // largest_double
      -largest,                                  // minus_largest_double
      std::numeric_limits<double>::quiet_NaN(),  // not_a_number
      inf,                                       // infinity
      -inf,                                      // minus_infinity
      -0.0,                                      // minus_zero
  };
  const auto index = static_cast<std::size_t>(base);
  return index < values.size() ? values[index] : 0.0;
}

double interesting_value(InterestingValue value) noexcept {
  // Exact for the bases up to 2^31, so those values stay on the 1/256 grid the oracle check needs.
  return base_value(value.base) + value.whole + value.fraction / 256.0;
}

RasterizerInput decode_rasterizer_input(std::span<const std::uint8_t> bytes) {
  ByteReader in(bytes);
  RasterizerInput input;
  input.algorithm_selector = in.byte();
  input.width = canvas_side(in.byte());
  input.height = canvas_side(in.byte());
  do {
    input.triangles.push_back(read_triangle(in));
  } while (!in.at_end() && input.triangles.size() < max_fuzz_triangles);
  return input;
}

RasterizerInputWriter::RasterizerInputWriter(std::uint8_t algorithm_selector, int width, int height)
    : bytes_{algorithm_selector, static_cast<std::uint8_t>(width - 1),
             static_cast<std::uint8_t>(height - 1)} {}

RasterizerInputWriter& RasterizerInputWriter::raw(const Triangle& vertices, Color color) {
  bytes_.push_back(0);
  append_color(bytes_, color);
  for (const glm::dvec2& v : vertices) {
    for (const double value : {v.x, v.y}) {
      const auto bits = std::bit_cast<std::uint64_t>(value);
      for (int i = 0; i < 8; ++i) bytes_.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
    }
  }
  return *this;
}

RasterizerInputWriter& RasterizerInputWriter::interesting(
    const std::array<InterestingValue, 6>& coordinates, Color color) {
  bytes_.push_back(1);
  append_color(bytes_, color);
  for (const InterestingValue& c : coordinates) {
    bytes_.insert(bytes_.end(), {static_cast<std::uint8_t>(c.base),
                                 static_cast<std::uint8_t>(c.whole), c.fraction});
  }
  return *this;
}

}  // namespace tri::fuzz
