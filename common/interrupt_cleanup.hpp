/// @file
/// What an interrupted run must remove: named temporaries and the folders made for its outputs.
/// SIGINT, SIGTERM, SIGHUP, SIGPIPE and SIGXFSZ (where the program left them at their default)
/// remove every registered path, then end the program by the same signal.
#pragma once

#include <filesystem>

namespace tri {

/// What a registered path is: a file is unlinked, a folder removed when empty (after the files).
enum class LeftoverKind { file, folder };

/// One path removed if a signal ends the program while it is registered; released by its end of
/// life or by release(). Registering installs the handler for each of those signals still at its
/// default.
class InterruptCleanup {
 public:
  InterruptCleanup() = default;
  InterruptCleanup(const std::filesystem::path& path, LeftoverKind kind);
  InterruptCleanup(InterruptCleanup&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }
  InterruptCleanup& operator=(InterruptCleanup&& other) noexcept;
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;
  ~InterruptCleanup() { release(); }

  /// The path is no longer removed on a signal (it was renamed, removed or is kept).
  void release();

 private:
  int slot_ = -1;  // -1: nothing registered (all slots taken, or a path too long)
};

}  // namespace tri
