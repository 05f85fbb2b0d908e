/// @file
/// What the chapters' registry tests share: an entry found by its name, and the claims every
/// chapter's list of entries makes (@ref design_registry "docs/DESIGN.md section 5").
#pragma once

#include <initializer_list>
#include <span>
#include <string_view>

#include "common/triangle_algorithm.hpp"

namespace tri::testing {

/// The entry of `algorithms` called `name`; fails the test when there is none.
const TriangleAlgorithm& algorithm_named(std::span<const TriangleAlgorithm> algorithms,
                                         std::string_view name);

/// Checks that a chapter registers exactly `names`, in that order, each under the chapter folder
/// `chapter` with the rule `rule`, a summary, a draw function, and a single thread.
void check_chapter_entries(std::span<const TriangleAlgorithm> algorithms, std::string_view chapter,
                           std::initializer_list<std::string_view> names, CoverageRule rule);

}  // namespace tri::testing
