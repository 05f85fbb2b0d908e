/// @file
/// How a fuzz target turns a finding into something libFuzzer records: print it, then abort, so
/// libFuzzer writes the input to a crash file.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace tri::fuzz {

/// Prints every finding to stderr and aborts when there is any; returns otherwise.
inline void abort_on_findings(const std::vector<std::string>& findings) {
  if (findings.empty()) return;
  for (const std::string& finding : findings)
    std::fprintf(stderr, "FINDING: %s\n", finding.c_str());
  std::abort();
}

}  // namespace tri::fuzz
