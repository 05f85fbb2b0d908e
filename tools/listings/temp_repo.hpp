#pragma once
/// @file
/// What the listings tool's tests share: a temporary repository and a look into a report.

#include <algorithm>
#include <filesystem>
#include <string>

#include "tests/support/scratch_folder.hpp"
#include "tools/listings/listings.hpp"

namespace tri::listings::testing {

namespace fs = std::filesystem;

// A fresh repository in a scratch folder, removed with everything in it at the end.
class TempRepo {
 public:
  const fs::path& root() const { return folder_.path(); }

  void write(const std::string& name, const std::string& text) const {
    const auto path = root() / name;
    fs::create_directories(path.parent_path());
    tri::testing::write_text(path, text);
  }

  std::string read(const std::string& name) const { return tri::testing::read_text(root() / name); }

 private:
  tri::testing::ScratchFolder folder_{"listings_test"};
};

// True when one of the report's problems, formatted, contains `part`.
inline bool any_problem_contains(const Report& report, const std::string& part) {
  return std::any_of(report.problems.begin(), report.problems.end(),
                     [&](const Problem& p) { return format(p).find(part) != std::string::npos; });
}

}  // namespace tri::listings::testing
