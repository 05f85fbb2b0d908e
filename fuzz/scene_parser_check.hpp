/// @file
/// The properties fuzz_scene_parser checks on every input; the regression tests apply the same
/// checks to the seed corpus and to past findings with the normal compiler.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/scene.hpp"

namespace tri::fuzz {

/// The promises an input broke, one line each; empty when every check held.
using Findings = std::vector<std::string>;

/// The source name the checks pass to parse_scene; every SceneError message must start with it.
inline constexpr std::string_view fuzz_source_name = "fuzz.scene";

/// Small limits the checks parse every text with a second time, so that a fuzzer's short inputs
/// reach the parser's limits, which the documented ones put at 64 KiB and 2,000,000 primitives.
inline constexpr SceneLimits fuzz_scene_limits{.max_line_bytes = 64, .max_primitives = 8};

/// What parse_scene did with one text.
struct ParseOutcome {
  bool parsed = false;             ///< a scene came back (with the documented limits)
  std::string error;               ///< the SceneError message, when one was thrown
  std::string small_limits_error;  ///< the SceneError message with fuzz_scene_limits, if any
  Findings findings;  ///< broken promises (other exceptions, contract violations), both parses
};

/// Checks a scene parse_scene returned: 1 <= width, height <= 16384, every coordinate finite
/// and within ±2^30, so every triangle passes validate_triangle, and at most the limits'
/// primitives.
Findings check_scene_contract(const Scene& scene, const SceneLimits& limits = {});

/// Feeds the text to parse_scene, with the documented limits and with fuzz_scene_limits, and
/// checks its contract each time (@ref design_scenes "docs/DESIGN.md section 4"):
///  - it either returns a scene or throws SceneError, nothing else;
///  - a SceneError message is one line that starts with "fuzz.scene:";
///  - a returned scene passes check_scene_contract.
ParseOutcome check_scene_parser(std::string_view text);

}  // namespace tri::fuzz
