/// @file
/// The repository's test-name convention (docs/DESIGN.md section 10), checked on the sources:
/// every TEST_CASE is a sentence tagged with its folder's prefix and, in a chapter, its step,
/// and every test a README quotes exists.
#pragma once

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace tri::conventions {

/// One TEST_CASE as written in a source file.
struct DeclaredTest {
  std::string name;               ///< the concatenated string literals of the first argument
  std::vector<std::string> tags;  ///< "[a][b]" split into {"a", "b"}
  int line = 0;                   ///< where TEST_CASE( stands, from 1
};

/// Every TEST_CASE in a C++ source text, with its name and tags.
std::vector<DeclaredTest> declared_tests(std::string_view source);

/// What breaks the convention in one test of a folder whose CTest prefix is `prefix`, or an
/// empty string. `steps` are the numbers of the "## Step N" headings of the chapter README (empty
/// outside chapters); `code` is the source text, where an identifier that starts the name must
/// occur.
std::string convention_problem(const DeclaredTest& test, std::string_view prefix,
                               const std::set<int>& steps, std::string_view code);

/// The numbers N of the "## Step N" headings in a README text.
std::set<int> step_numbers(std::string_view readme);

/// The test names a README quotes after "Test:" or "Tests:", with line breaks and runs of
/// spaces folded to one space, each with the line of its opening quote.
std::map<std::string, int> quoted_test_names(std::string_view readme);

}  // namespace tri::conventions
