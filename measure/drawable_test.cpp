#include "measure/drawable.hpp"

#include <catch2/catch.hpp>

#include <map>

#include "measure/registry.hpp"

namespace tri {
namespace {

TEST_CASE("Every registered algorithm is described once, with one entry point of its kind",
          "[measure][drawables]") {
  const auto drawables = registered_drawables();
  CHECK(drawables.size() == registered_algorithms().size() + registered_area_algorithms().size());
  for (const Drawable& d : drawables) {
    INFO(d.name);
    CHECK(find_named(drawables, d.name) == &d);  // names are unique
    REQUIRE((d.colours == nullptr) != (d.coverage == nullptr));
    if (d.colours != nullptr) {
      CHECK(d.name == d.colours->name);
      CHECK(d.writes(Output::rgba8));
      CHECK(d.writes(Output::counts));
      CHECK_FALSE(d.writes(Output::coverage16));
      CHECK(d.keeps_state == (d.colours->make_renderer != nullptr));
      CHECK(d.threaded == d.colours->threaded);
      CHECK(d.rule != CoverageRule::area);
    } else {
      CHECK(d.name == d.coverage->name);
      CHECK(d.outputs == coverage_outputs);
      CHECK(d.rule == CoverageRule::area);
    }
  }
}

TEST_CASE("Each role a measuring program asks for is declared by exactly one algorithm",
          "[measure][drawables]") {
  std::map<Role, int> declared;
  for (const Drawable& d : registered_drawables()) ++declared[d.role];
  for (const Role role :
       {Role::oracle, Role::speed_baseline, Role::fast_exact_starting, Role::cost_sweeps}) {
    CHECK(declared[role] == 1);
  }
  const auto algorithms = registered_algorithms();
  const TriangleAlgorithm* oracle = algorithm_with_role(algorithms, Role::oracle);
  REQUIRE(oracle != nullptr);
  CHECK(oracle->rule == CoverageRule::top_left);
}

TEST_CASE("drawables_writing finds the drawables that declare an output, in order",
          "[measure][drawables]") {
  const auto drawables = registered_drawables();
  CHECK(drawables_writing(drawables, Output::rgba8).size() == registered_algorithms().size());
  CHECK(drawables_writing(drawables, Output::coverage16).size() ==
        registered_area_algorithms().size());
  const auto narrow = drawables_writing(drawables, Output::mask1);
  REQUIRE(!narrow.empty());
  for (const Drawable* d : narrow) CHECK(d->writes(Output::index8));
}

}  // namespace
}  // namespace tri
