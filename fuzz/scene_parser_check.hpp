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

/// What parse_scene did with one text.
struct ParseOutcome {
  bool parsed = false;  ///< a scene came back
  std::string error;    ///< the SceneError message, when one was thrown
  Findings findings;    ///< broken promises (other exceptions, contract violations)
};

/// Checks a scene parse_scene returned: 1 <= width, height <= 16384, and every coordinate finite
/// and within ±2^30, so every triangle passes validate_triangle.
Findings check_scene_contract(const Scene& scene);

/// Feeds the text to parse_scene and checks its contract
/// (@ref design_scenes "docs/DESIGN.md section 4"):
///  - it either returns a scene or throws SceneError, nothing else;
///  - a SceneError message is one line that starts with "fuzz.scene:";
///  - a returned scene passes check_scene_contract.
ParseOutcome check_scene_parser(std::string_view text);

}  // namespace tri::fuzz
