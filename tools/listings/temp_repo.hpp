#pragma once
/// @file
/// What the listings tool's tests share: a temporary repository and a look into a report.

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "tools/listings/listings.hpp"

namespace tri::listings::testing {

namespace fs = std::filesystem;

// A fresh folder under the system's temporary folder, removed with everything in it at the end.
class TempRepo {
 public:
  TempRepo() {
    // The clock and a random number: CTest runs the tests in parallel processes.
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    root_ = fs::temp_directory_path() / ("listings_test_" + std::to_string(stamp) + "_" +
                                         std::to_string(std::random_device{}()));
    fs::create_directories(root_);
  }
  TempRepo(const TempRepo&) = delete;
  TempRepo& operator=(const TempRepo&) = delete;
  ~TempRepo() {
    std::error_code ignored;
    fs::remove_all(root_, ignored);
  }

  const fs::path& root() const { return root_; }

  void write(const std::string& name, const std::string& text) const {
    const auto path = root_ / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
  }

  std::string read(const std::string& name) const {
    std::ifstream in(root_ / name, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

 private:
  fs::path root_;
};

// True when one of the report's problems, formatted, contains `part`.
inline bool any_problem_contains(const Report& report, const std::string& part) {
  return std::any_of(report.problems.begin(), report.problems.end(),
                     [&](const Problem& p) { return format(p).find(part) != std::string::npos; });
}

}  // namespace tri::listings::testing
