#include "tests/support/registry_checks.hpp"

#include <stdexcept>

#include <catch2/catch.hpp>

namespace tri::testing {

const TriangleAlgorithm& algorithm_named(std::span<const TriangleAlgorithm> algorithms,
                                         std::string_view name) {
  for (const TriangleAlgorithm& algorithm : algorithms) {
    if (algorithm.name == name) return algorithm;
  }
  FAIL("no algorithm named " << name);
  throw std::logic_error("unreachable: FAIL throws");
}

void check_chapter_entries(std::span<const TriangleAlgorithm> algorithms, std::string_view chapter,
                           std::initializer_list<std::string_view> names, CoverageRule rule) {
  REQUIRE(algorithms.size() == names.size());
  const TriangleAlgorithm* algorithm = algorithms.data();
  for (const std::string_view name : names) {
    CHECK(algorithm->name == name);
    CHECK(algorithm->chapter == chapter);
    CHECK(algorithm->rule == rule);
    CHECK_FALSE(algorithm->summary.empty());
    CHECK(algorithm->draw != nullptr);
    CHECK_FALSE(algorithm->threaded);
    ++algorithm;
  }
}

}  // namespace tri::testing
