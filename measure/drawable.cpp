#include "measure/drawable.hpp"

#include <algorithm>

namespace tri {

Drawable describe(const TriangleAlgorithm& algorithm) noexcept {
  return {.name = algorithm.name,
          .chapter = algorithm.chapter,
          .summary = algorithm.summary,
          .rule = algorithm.rule,
          .outputs = algorithm.outputs,
          .threaded = algorithm.threaded,
          .keeps_state = algorithm.make_renderer != nullptr,
          .role = algorithm.role,
          .colours = &algorithm};
}

Drawable describe(const ch09::AreaAlgorithm& algorithm) noexcept {
  return {.name = algorithm.name,
          .chapter = algorithm.chapter,
          .summary = algorithm.summary,
          .rule = algorithm.rule,
          .outputs = coverage_outputs,
          .coverage = &algorithm};
}

std::vector<Drawable> describe_all(std::span<const TriangleAlgorithm> colours,
                                   std::span<const ch09::AreaAlgorithm> coverage) {
  std::vector<Drawable> all;
  for (const TriangleAlgorithm& a : colours) all.push_back(describe(a));
  for (const ch09::AreaAlgorithm& a : coverage) all.push_back(describe(a));
  return all;
}

std::vector<const Drawable*> drawables_writing(std::span<const Drawable> drawables, Output output) {
  std::vector<const Drawable*> found;
  for (const Drawable& d : drawables) {
    if (d.writes(output)) found.push_back(&d);
  }
  return found;
}

std::vector<TriangleAlgorithm> colour_algorithms(std::span<const Drawable> drawables) {
  std::vector<TriangleAlgorithm> found;
  for (const Drawable& d : drawables) {
    if (d.colours != nullptr) found.push_back(*d.colours);
  }
  return found;
}

}  // namespace tri
