#include "measure/registry.hpp"

#include <algorithm>

#include "chapters/03_interpolate_fill/algorithms.hpp"
#include "chapters/04_scanline/algorithms.hpp"
#include "chapters/05_edge_function/algorithms.hpp"
#include "chapters/06_barycentric/algorithms.hpp"
#include "chapters/07_exact_coverage/algorithms.hpp"
#include "chapters/08_fast_exact/algorithms.hpp"

namespace tri {

namespace {

// Visits each chapter's own registration, in chapter order: every list here is made from these.
template <class Visit>
void for_each_registered(Visit visit) {
  for (const auto chapter :
       {ch03::triangle_algorithms(), ch04::triangle_algorithms(), ch05::triangle_algorithms(),
        ch06::triangle_algorithms(), ch07::triangle_algorithms(), ch08::triangle_algorithms()}) {
    for (const TriangleAlgorithm& a : chapter) visit(a);
  }
}

}  // namespace

std::vector<TriangleAlgorithm> registered_algorithms() {
  std::vector<TriangleAlgorithm> all;
  for_each_registered([&](const TriangleAlgorithm& a) { all.push_back(a); });
  return all;
}

std::vector<Drawable> registered_drawables() {
  std::vector<Drawable> all;
  for_each_registered([&](const TriangleAlgorithm& a) { all.push_back(describe(a)); });
  for (const ch09::AreaAlgorithm& a : ch09::area_algorithms()) all.push_back(describe(a));
  return all;
}

std::vector<ch09::AreaAlgorithm> registered_area_algorithms() {
  const auto chapter = ch09::area_algorithms();
  return {chapter.begin(), chapter.end()};
}

}  // namespace tri
