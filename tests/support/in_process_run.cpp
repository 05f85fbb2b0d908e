#include "tests/support/in_process_run.hpp"

#include <sstream>

namespace tri::testing {

InProcessRun run_in_process(std::string_view program, const std::vector<std::string>& args,
                            const ProgramEntry& entry) {
  const std::string name(program);
  std::vector<const char*> argv{name.c_str()};
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int status = entry(static_cast<int>(argv.size()), argv.data(), out, err);
  return {status, out.str(), err.str()};
}

}  // namespace tri::testing
