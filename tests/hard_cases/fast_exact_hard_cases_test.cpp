// The repository's hard cases (tests/hard_cases) run on this chapter's variants here as well, so
// that `ctest -R 08_fast_exact` alone shows whether a change to the chapter broke one.
#include <catch2/catch.hpp>

#include "chapters/08_fast_exact/algorithms.hpp"
#include "measure/hard_cases.hpp"
#include "tests/hard_cases/deviation_checks.hpp"

TEST_CASE("Every variant of the chapter is safe and exact on every hard case", "[hard_cases]") {
  for (const auto& algorithm : tri::ch08::triangle_algorithms()) {
    for (const auto& c : tri::hard_cases::all_cases()) {
      INFO(algorithm.name << " on " << c.name);
      const auto outcome = tri::hard_cases::run_case(algorithm, c);
      CHECK(outcome.safe);
      CHECK(outcome.error.outside_writes == 0);
      tri::testing::check_no_deviation(outcome.error);
    }
  }
}
