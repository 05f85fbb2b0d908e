/// @file
/// The suite's named tests (docs/DESIGN.md section 9, the conformance suite): each checks one
/// promise of a rasterizer on a few small seeded scenes, its cases.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "chapters/11_your_rasterizer/graded_rasterizer.hpp"
#include "common/scene.hpp"

namespace tri::conformance {

/// What a case's write counts are compared with.
enum class Check {
  rule,        ///< what the graded tie rule expects, pixel for pixel
  consistent,  ///< what any consistent rule allows: exact except at ties, no holes, no doubles
  relation,    ///< only the relation to an earlier case (same_as)
};

/// A case whose counts must equal an earlier case's counts moved by a whole-pixel shift.
struct Relation {
  std::size_t base = 0;  ///< index of the earlier case in the same test
  glm::ivec2 shift{0, 0};
};

/// One scene of a test and how its answer is judged.
struct TestCase {
  std::string label;  ///< e.g. "fan_integer" or "random extent 2-8, order 4"
  Scene scene;
  Check check = Check::rule;
  std::optional<Relation> same_as;
  Threads threads = Threads::all;
  bool only_threaded = false;  ///< drawn only for a rasterizer that declares threads
  bool bad_input = false;      ///< holds NaN or infinite vertices: refusing the scene passes
};

/// One promise and the cases that check it.
struct NamedTest {
  std::string name;     ///< stable, lower case with underscores: the scorecard's `test` column
  std::string promise;  ///< one line
  std::vector<TestCase> cases;
};

/// Every named test, in a fixed order, with the same scenes on every call.
std::vector<NamedTest> named_tests();

}  // namespace tri::conformance
