#include "measure/process_memory.hpp"

#include <malloc.h>

#include <fstream>
#include <stdexcept>
#include <string>

namespace tri {
namespace {

// A "Name:   1234 kB" line of /proc/self/status, in bytes.
std::uint64_t status_bytes(const std::string& name) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.starts_with(name + ':')) return std::stoull(line.substr(name.size() + 1)) * 1024;
  }
  throw std::runtime_error("/proc/self/status has no " + name + " line (not Linux?)");
}

}  // namespace

void release_free_heap() noexcept {
  ::malloc_trim(0);
}

std::uint64_t resident_bytes() {
  return status_bytes("VmRSS");
}

std::uint64_t peak_resident_bytes() {
  return status_bytes("VmHWM");
}

void reset_peak_resident() {
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5";
  clear_refs.close();
  if (!clear_refs) throw std::runtime_error("cannot reset the peak resident size");
}

}  // namespace tri
