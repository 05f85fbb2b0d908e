/// @file
/// The tie rule a rasterizer is graded under, and the write counts each rule expects of a scene:
/// chapter 07's exact oracle (top-left), the oracle mirrored top to bottom (bottom-left), or the
/// range the four mirrored oracles span (any consistent rule: exact except at ties, watertight).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "common/drawable.hpp"
#include "common/scene.hpp"

namespace tri::conformance {

/// Which centres exactly on an edge a rasterizer must cover.
enum class TieRule {
  top_left,     ///< the book's rule (docs/DESIGN.md section 6), Direct3D's
  bottom_left,  ///< the top-left rule mirrored top to bottom, as llvmpipe draws in our coordinates
  any,          ///< any consistent rule: exact except at ties, and watertight
};

/// "top-left", "bottom-left" or "any".
std::string_view tie_rule_name(TieRule rule) noexcept;
/// The rule a name gives, or nothing for another word.
std::optional<TieRule> parse_tie_rule(std::string_view name) noexcept;

/// The tie rule a registered algorithm is graded under: the exact rule it declares, else top-left
/// (so that an approximate algorithm shows its errors against the truth).
TieRule declared_tie_rule(CoverageRule rule) noexcept;

/// The write counts a rule allows, pixel by pixel (bottom row first, as Canvas::write_counts): a
/// count c passes when low <= c <= high. For an exact rule low and high are equal.
struct ExpectedCounts {
  std::vector<std::uint32_t> low;
  std::vector<std::uint32_t> high;
};

/// What the rule expects of the scene's triangles: each finite triangle within ±2^30 drawn by the
/// oracle under that rule (the others draw nothing). Under `any`, each pixel's range spans the
/// oracle mirrored in x, in y and in both: every consistent axis-aligned tie rule.
ExpectedCounts expected_counts(const Scene& scene, TieRule rule);

}  // namespace tri::conformance
