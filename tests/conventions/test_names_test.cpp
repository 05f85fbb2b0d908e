#include "tests/conventions/test_names.hpp"

#include <catch2/catch.hpp>

#include <string>

namespace tri::conventions {
namespace {

DeclaredTest only_test(const std::string& source) {
  const auto tests = declared_tests(source);
  REQUIRE(tests.size() == 1);
  return tests.front();
}

TEST_CASE("A TEST_CASE's name joins its string literals and its tags are split",
          "[conventions][parsing]") {
  const auto test = only_test(
      "#include <x>\n\nTEST_CASE(\"Two \"\n          \"parts, one \\\"quote\\\"\", "
      "\"[01_lines][step2]\") {}\n");
  CHECK(test.name == "Two parts, one \"quote\"");
  CHECK(test.tags == std::vector<std::string>{"01_lines", "step2"});
  CHECK(test.line == 3);
}

TEST_CASE("A name in lower case passes only when its first word is an identifier of the code",
          "[conventions][names]") {
  const std::string code =
      "TEST_CASE(\"interpolate returns\", \"[01_lines][step2]\") {\n"
      "  interpolate(0, 0, 1, 1);\n}\n";
  const auto test = only_test(code);
  CHECK(convention_problem(test, "01_lines", {2}, code).empty());
  const std::string prose = "TEST_CASE(\"the line is exact\", \"[01_lines][step2]\") {}\n";
  CHECK_FALSE(convention_problem(only_test(prose), "01_lines", {2}, prose).empty());
  // A word that occurs only inside a string literal or a comment is not code.
  const std::string quoted = "TEST_CASE(\"the line\", \"[01_lines][step2]\") { // the\n}\n";
  CHECK_FALSE(convention_problem(only_test(quoted), "01_lines", {2}, quoted).empty());
}

TEST_CASE("A name with a semicolon fails, since CTest would split it into two tests",
          "[conventions][names]") {
  const std::string split = "TEST_CASE(\"It holds; it runs\", \"[common]\") {}\n";
  CHECK_THAT(convention_problem(only_test(split), "common", {}, split), Catch::Contains("';'"));
  const std::string whole = "TEST_CASE(\"It holds, it runs\", \"[common]\") {}\n";
  CHECK(convention_problem(only_test(whole), "common", {}, whole).empty());
}

TEST_CASE("The first tag must be the folder's prefix and a chapter needs a real step",
          "[conventions][tags]") {
  const std::string untagged = "TEST_CASE(\"It holds\") {}\n";
  CHECK_FALSE(convention_problem(only_test(untagged), "common", {}, untagged).empty());
  const std::string other = "TEST_CASE(\"It holds\", \"[02_wireframe][step1]\") {}\n";
  CHECK_FALSE(convention_problem(only_test(other), "01_lines", {1}, other).empty());
  const std::string no_step = "TEST_CASE(\"It holds\", \"[01_lines]\") {}\n";
  CHECK_FALSE(convention_problem(only_test(no_step), "01_lines", {1}, no_step).empty());
  const std::string missing = "TEST_CASE(\"It holds\", \"[01_lines][step7]\") {}\n";
  CHECK_FALSE(convention_problem(only_test(missing), "01_lines", {1, 2}, missing).empty());
  const std::string good = "TEST_CASE(\"It holds\", \"[01_lines][step2]\") {}\n";
  CHECK(convention_problem(only_test(good), "01_lines", {1, 2}, good).empty());
  const std::string folder = "TEST_CASE(\"It holds\", \"[common]\") {}\n";
  CHECK(convention_problem(only_test(folder), "common", {}, folder).empty());
  const std::string stop = "TEST_CASE(\"It holds.\", \"[common]\") {}\n";
  CHECK_FALSE(convention_problem(only_test(stop), "common", {}, stop).empty());
}

TEST_CASE("A README's steps and quoted test names are read across line breaks",
          "[conventions][readme]") {
  const std::string readme =
      "# Chapter\n## Step 1: a\ntext\n## Step 3: c\n"
      "Code: `f()` · Test: \"The first\nname\", \"The second\" and \"The third\".\n"
      "Tests: \"The fourth\".\n";
  CHECK(step_numbers(readme) == std::set<int>{1, 3});
  const auto quoted = quoted_test_names(readme);
  CHECK(quoted.size() == 4);
  CHECK(quoted.count("The first name") == 1);
  CHECK(quoted.count("The second") == 1);
  CHECK(quoted.count("The third") == 1);
  CHECK(quoted.count("The fourth") == 1);
}

}  // namespace
}  // namespace tri::conventions
