#include "measure/machine.hpp"

#include <fstream>
#include <thread>
#include <utility>

namespace tri {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::string compiler_name() {
#if defined(__clang__)
  return "Clang " __clang_version__;
#elif defined(__GNUC__)
  return "GCC " __VERSION__;
#else
  return "unknown compiler";
#endif
}

}  // namespace

std::string cpu_model_from(std::istream& cpuinfo) {
  std::string line;
  while (std::getline(cpuinfo, line)) {
    const auto colon = line.find(':');
    if (colon == std::string::npos || trimmed(line.substr(0, colon)) != "model name") continue;
    const std::string model = trimmed(line.substr(colon + 1));
    return model.empty() ? "unknown" : model;
  }
  return "unknown";
}

Machine describe_machine(std::string external_peers) {
  Machine machine;
  machine.threads = std::thread::hardware_concurrency();
  std::ifstream cpuinfo("/proc/cpuinfo");
  machine.cpu_model = cpuinfo ? cpu_model_from(cpuinfo) : "unknown";
  machine.compiler = compiler_name();
  machine.build_type = TUTORIAL_BUILD_TYPE;
  if (machine.build_type.empty()) machine.build_type = "none given (CMAKE_BUILD_TYPE empty)";
  machine.external_peers = std::move(external_peers);
  return machine;
}

}  // namespace tri
