/// @file
/// What the numbers were measured on: cores, CPU model, compiler, build type, optional peers.
#pragma once

#include <istream>
#include <span>
#include <string>

namespace tri {
struct ExternalPeer;
}  // namespace tri

namespace tri::ch10 {

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

/// Describes this machine and this build, and the external peers a run measures.
Machine describe_machine(std::span<const ExternalPeer> measured_peers);

}  // namespace tri::ch10
