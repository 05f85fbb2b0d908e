/// @file
/// The one description of everything the registry can draw with: the book's colour algorithms and
/// its coverage algorithms, each with what it declares it can do
/// (@ref design_registry "docs/DESIGN.md section 5"). Programs ask a Drawable, never a name.
#pragma once

#include <algorithm>
#include <iterator>
#include <span>
#include <string_view>
#include <vector>

#include "chapters/09_anti_aliasing/area_algorithms.hpp"
#include "common/drawable.hpp"
#include "common/triangle_algorithm.hpp"

namespace tri {

/// A registered drawable: its description, its declared capabilities, and its entry points
/// (exactly one of `colours` and `coverage` is set; both point into the chapter's registration).
struct Drawable {
  std::string_view name;     ///< stable name, e.g. "fast_spans"
  std::string_view chapter;  ///< chapter folder, e.g. "08_fast_exact"
  std::string_view summary;  ///< one line for `raster --list`
  CoverageRule rule = CoverageRule::approximate;
  Outputs outputs = colour_outputs;  ///< what it can write
  bool threaded = false;             ///< uses more than one thread
  bool keeps_state = false;          ///< offers a batch renderer that keeps state between batches
  Role role = Role::none;
  const TriangleAlgorithm* colours = nullptr;     ///< draws colours: rgba8 and its counts
  const ch09::AreaAlgorithm* coverage = nullptr;  ///< draws fractions of pixels

  /// Whether it can write `output`.
  bool writes(Output output) const noexcept { return outputs.has(output); }
};

/// The description of a colour algorithm (which must outlive it).
Drawable describe(const TriangleAlgorithm& algorithm) noexcept;
/// The description of a coverage algorithm (which must outlive it).
Drawable describe(const ch09::AreaAlgorithm& algorithm) noexcept;

/// The descriptions of these algorithms, colour ones first, each list in its order.
std::vector<Drawable> describe_all(std::span<const TriangleAlgorithm> colours,
                                   std::span<const ch09::AreaAlgorithm> coverage);

/// The entry with this name in a list of named entries (drawables, algorithms, peers), or nullptr:
/// the one lookup by name, so every list is searched the same way.
template <class Entries>
auto find_named(const Entries& entries, std::string_view name) noexcept
    -> decltype(&*std::begin(entries)) {
  // std::find_if, not std::ranges: the playground's libc++ has no ranges algorithms yet.
  const auto it = std::find_if(std::begin(entries), std::end(entries),
                               [&](const auto& e) { return e.name == name; });
  return it == std::end(entries) ? nullptr : &*it;
}

/// The drawables that can write `output`, in order.
std::vector<const Drawable*> drawables_writing(std::span<const Drawable> drawables, Output output);

/// The colour algorithms among the drawables, in order.
std::vector<TriangleAlgorithm> colour_algorithms(std::span<const Drawable> drawables);

}  // namespace tri
