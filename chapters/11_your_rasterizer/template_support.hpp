// What the template's tests share: the failed tests of a scorecard folder.
#pragma once

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

namespace tri::ch11::test {

/// The tests whose verdict is fail in folder/scorecard.csv (test,verdict,...).
inline std::set<std::string> failed_in_scorecard(const std::filesystem::path& folder) {
  std::ifstream csv(folder / "scorecard.csv");
  std::set<std::string> failed;
  std::string line;
  std::getline(csv, line);  // the header
  while (std::getline(csv, line)) {
    const auto first = line.find(',');
    if (line.compare(first + 1, 5, "fail,") == 0) failed.insert(line.substr(0, first));
  }
  return failed;
}

}  // namespace tri::ch11::test
