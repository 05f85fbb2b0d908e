/// @file
/// What the numbers were measured on: cores, CPU model, compiler, build type, optional peers.
#pragma once

#include <istream>
#include <string>

namespace tri {

/// The machine and build a report was measured with.
struct Machine {
  unsigned threads = 0;        ///< std::thread::hardware_concurrency (what nproc prints)
  std::string cpu_model;       ///< "model name" of /proc/cpuinfo, or "unknown"
  std::string compiler;        ///< compiler and version this report was built with
  std::string build_type;      ///< CMake build type, e.g. "Release"
  std::string external_peers;  ///< one line on the optional peers: measured, or why not
};

/// The value of the first "model name" line of a /proc/cpuinfo text, or "unknown".
std::string cpu_model_from(std::istream& cpuinfo);

/// Describes this machine and this build; `external_peers` is the line on the peers a run
/// measures (the report's external_peer_status).
Machine describe_machine(std::string external_peers);

}  // namespace tri
