// check_test_names ROOT --prefix P FILE... [--prefix Q FILE...]...
// Checks every TEST_CASE in the files against the test-name convention of docs/DESIGN.md
// section 10 (FILEs after --prefix P belong to the folder whose CTest prefix is P), and that
// every test name the READMEs and the design document quote exists. Prints one line a problem;
// exits 1 when there is one, 2 on bad arguments.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/conventions/test_names.hpp"

namespace fs = std::filesystem;
using namespace tri::conventions;

namespace {

std::string read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The names of the tests CMake adds itself (add_test(NAME "prefix/name" ...)) and of every
// TEST_CASE in a *_test.cpp file, registered in this build or not: a README may quote a test of
// an optional part (an external peer) that this build leaves out.
void add_other_test_names(const fs::path& root, std::set<std::string>& names) {
  static const std::regex added(R"(add_test\(NAME\s+"[^/"]+/([^"]+)\")");
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    const auto relative = fs::relative(entry.path(), root).string();
    if (relative.rfind("build", 0) == 0 || relative.rfind(".git", 0) == 0) continue;
    const std::string file = entry.path().filename().string();
    if (file.size() > 9 && file.compare(file.size() - 9, 9, "_test.cpp") == 0) {
      for (const auto& test : declared_tests(read(entry.path()))) names.insert(test.name);
    }
    if (file != "CMakeLists.txt") continue;
    const std::string text = read(entry.path());
    for (auto it = std::sregex_iterator(text.begin(), text.end(), added);
         it != std::sregex_iterator(); ++it) {
      names.insert((*it)[1].str());
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: check_test_names ROOT --prefix P FILE... [--prefix Q FILE...]...\n";
    return 2;
  }
  try {
    const fs::path root = argv[1];
    std::set<std::string> names;
    int problems = 0;
    std::string prefix;
    for (int i = 2; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--prefix" && i + 1 < argc) {
        prefix = argv[++i];
        continue;
      }
      if (prefix.empty()) throw std::runtime_error("a file before any --prefix: " + arg);
      const fs::path readme = root / "chapters" / prefix / "README.md";
      const std::set<int> steps = fs::exists(readme) ? step_numbers(read(readme)) : std::set<int>{};
      const std::string source = read(arg);
      for (const auto& test : declared_tests(source)) {
        names.insert(test.name);
        const std::string problem = convention_problem(test, prefix, steps, source);
        if (!problem.empty()) {
          std::cout << arg << ':' << test.line << ": " << problem << ": \"" << test.name << "\"\n";
          ++problems;
        }
      }
    }
    add_other_test_names(root, names);
    std::vector<fs::path> pages = {root / "README.md", root / "docs" / "DESIGN.md",
                                   root / "fuzz" / "README.md"};
    for (const auto& entry : fs::directory_iterator(root / "chapters")) {
      if (fs::exists(entry.path() / "README.md")) pages.push_back(entry.path() / "README.md");
    }
    int quotes = 0;
    for (const auto& page : pages) {
      for (const auto& [name, line] : quoted_test_names(read(page))) {
        ++quotes;
        if (names.count(name) == 0) {
          std::cout << page.string() << ':' << line << ": quotes a test that does not exist: \""
                    << name << "\"\n";
          ++problems;
        }
      }
    }
    std::cout << names.size() << " test names, " << quotes << " quoted in the READMEs\n";
    if (problems > 0) {
      std::cout << problems << " problem(s); the convention is in docs/DESIGN.md section 10\n";
      return 1;
    }
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "check_test_names: " << error.what() << '\n';
    return 2;
  }
}
