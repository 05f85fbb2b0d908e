/// @file
/// The descriptor convention (docs/DESIGN.md section 5): outside the chapters' registrations and
/// the tests, no code compares a string with a registered name, since what a drawable can do is
/// what it declares, not what it is called.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tri::conventions {

/// One comparison with a registered name, e.g. `name == "fast_spans"`.
struct NameComparison {
  std::string name;  ///< the registered name compared with
  int line = 0;      ///< where it stands, from 1
};

/// Every `== "NAME"`, `!= "NAME"`, `"NAME" ==`, `"NAME" !=`, `starts_with("NAME")` and
/// `= "NAME";` (a constant that holds a name to compare with later) in a source text, where NAME
/// is one of `names`.
std::vector<NameComparison> name_comparisons(std::string_view source,
                                             std::span<const std::string_view> names);

/// Whether the convention applies to a file (a path relative to the repository's root): C++ and
/// JavaScript sources outside the tests (*_test.cpp, tests/, fuzz/regressions/), the chapters'
/// registrations (algorithms.cpp, area_algorithms.cpp) and the build folders.
bool checked_for_name_comparisons(const std::filesystem::path& relative);

}  // namespace tri::conventions
