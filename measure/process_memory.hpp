/// @file
/// How much memory this process holds, read from Linux's /proc/self: the scaling sweeps report
/// the peak resident memory that drawing a scene adds.
#pragma once

#include <cstdint>

namespace tri {

/// Gives the heap's free memory back to the system (glibc's malloc_trim), so that memory allocated
/// afterwards is counted when it is first written, not found already resident.
void release_free_heap() noexcept;

/// Bytes of this process resident in memory now (VmRSS).
std::uint64_t resident_bytes();

/// The most bytes resident at once since the process started or reset_peak_resident() (VmHWM);
/// a forked child's peak starts at what it inherited, not at its parent's peak.
std::uint64_t peak_resident_bytes();

/// Starts a new peak at today's resident size (writes 5 to /proc/self/clear_refs, Linux 4.0 on).
/// Throws std::runtime_error where the kernel does not allow it.
void reset_peak_resident();

}  // namespace tri
