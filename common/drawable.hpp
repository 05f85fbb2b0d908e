/// @file
/// What a registered drawable declares it can do, so that no program decides a capability by an
/// algorithm's name (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace tri {

/// What an algorithm claims about the pixels it covers.
enum class CoverageRule {
  top_left,     ///< exact coverage: centres strictly inside, ties by the top-left rule
  bottom_left,  ///< exact coverage, ties by the top-left rule mirrored (a y-down peer, llvmpipe)
  inclusive,    ///< centres on an edge are always covered (the articles' methods)
  approximate,  ///< no exactness claimed
  area,         ///< a fraction of each pixel, not a yes or no (chapter 09's coverage algorithms)
};

/// The name `raster --list` and the report print for a rule: "top-left", "bottom-left",
/// "inclusive", "approximate" or "area".
std::string_view rule_name(CoverageRule rule) noexcept;

/// Something a drawable can write.
enum class Output : std::uint8_t {
  rgba8 = 1,        ///< the colour canvas
  index8 = 2,       ///< one byte per pixel, a palette index (chapter 08, step 8)
  mask1 = 4,        ///< one bit per pixel (chapter 08, step 8)
  counts = 8,       ///< how often each pixel was written
  coverage16 = 16,  ///< each pixel's covered fraction, as 16 bits
};

/// A set of outputs.
class Outputs {
 public:
  constexpr Outputs(std::initializer_list<Output> outputs) noexcept {
    for (const Output o : outputs) bits_ |= static_cast<std::uint8_t>(o);
  }
  constexpr bool has(Output output) const noexcept {
    return (bits_ & static_cast<std::uint8_t>(output)) != 0;
  }
  constexpr bool operator==(const Outputs&) const noexcept = default;

 private:
  std::uint8_t bits_ = 0;
};

/// What every colour algorithm writes: the RGBA8 canvas and its write counts.
inline constexpr Outputs colour_outputs{Output::rgba8, Output::counts};
/// A colour algorithm that also draws chapter 08's narrow canvases.
inline constexpr Outputs narrow_outputs{Output::rgba8, Output::counts, Output::index8,
                                        Output::mask1};
/// What a coverage algorithm writes: fractions, kept as 16 bits.
inline constexpr Outputs coverage_outputs{Output::coverage16};

/// A part a measuring program gives one drawable, declared where it is registered.
enum class Role : std::uint8_t {
  none,
  oracle,               ///< the truth every error is measured against
  speed_baseline,       ///< chapter 08's benchmark divides the other rows' times by its time
  fast_exact_starting,  ///< the exact algorithm chapter 08 starts from, benchmarked beside it
  cost_sweeps,          ///< the algorithm the report's sweeps follow as the canvas and scene grow
};

}  // namespace tri
