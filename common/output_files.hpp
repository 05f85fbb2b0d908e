/// @file
/// Writing output files without ever losing one: every program writes through this file.
///
/// The promises (docs/DESIGN.md section 9, "Writing files"):
/// - Data goes to an unnamed temporary file (O_TMPFILE) in the target's folder, or where the file
///   system has none to a new ".NAME.XXXXXX.tmp" created exclusively (never following a link); it
///   is synced and put in place only when every output of the run is complete: given a fresh
///   temporary name (linkat) and renamed over the target, one output at a time, under an
///   exclusive flock() on each target's folder so that two runs commit their sets one after the
///   other. A failure removes the temporaries and the folders made for the outputs and leaves
///   every earlier file as it was; SIGINT, SIGTERM, SIGHUP, SIGPIPE and SIGXFSZ remove them too
///   (common/interrupt_cleanup.hpp).
/// - A symbolic link as target is written through: its target file is replaced, the link stays;
///   a link in a sticky world-writable folder owned by neither the folder's owner nor this user
///   is refused, as the kernel's protected_symlinks check would.
/// - A replaced file keeps its owner, group and permission bits where this user may set them,
///   never its setuid, setgid or sticky bits.
/// - A target with several hard links is refused (replacing one name would split them silently).
/// - A target that is not a regular file (folder, device, FIFO, socket) is refused, never
///   replaced; so is a target this user may not write (Permission denied), and a name ending in
///   a slash (a usage error).
/// - An output that is also an input (same device and inode) or two outputs naming one file are
///   refused before any work. "-" means standard output where a program allows it; /dev/stdout,
///   /dev/stderr, /dev/fd/N and /proc/self/fd/N name a descriptor, which is written to as "-" is
///   (never replaced by a file), and before any file is replaced.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include "common/interrupt_cleanup.hpp"

namespace tri {

/// An output that cannot be written; what() names the path and the system's reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The output name that means standard output.
inline constexpr std::string_view standard_output_name = "-";

/// The descriptor an output names ("-" is 1, /dev/stderr 2, /dev/fd/N N), or nothing for a file.
std::optional<int> output_descriptor(const std::filesystem::path& output);

/// Checks a run's outputs before any work: throws UsageError for an empty path, a name ending in
/// a slash, two outputs naming one file or an output that is one of the inputs, and OutputError for
/// a target that could not be replaced (see the promises above) or a folder that could not be
/// created.
void check_outputs(std::span<const std::filesystem::path> outputs,
                   std::span<const std::filesystem::path> inputs = {});

/// Checks before any work that files can be written into folder (existing or creatable).
void check_output_folder(const std::filesystem::path& folder);

/// Where a transaction writes its data before the commit.
enum class TemporaryFiles {
  unnamed_where_supported,  // O_TMPFILE, else named: nothing is left whatever ends the run
  named,                    // always ".NAME.XXXXXX.tmp" (what file systems without O_TMPFILE get)
};

/// Several outputs that replace their targets together: stage each, then commit. Whatever was
/// staged but not committed is removed when the transaction ends.
class OutputTransaction {
 public:
  /// standard_output receives the outputs named "-"; without it "-" is refused.
  explicit OutputTransaction(std::ostream* standard_output = nullptr,
                             TemporaryFiles temporaries = TemporaryFiles::unnamed_where_supported)
      : standard_output_(standard_output), temporaries_(temporaries) {}
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;
  ~OutputTransaction();

  /// Writes bytes to a new temporary beside target (creating missing folders), or keeps them for
  /// the descriptor the target names. Throws OutputError.
  void stage(const std::filesystem::path& target, std::span<const std::uint8_t> bytes);
  /// Writes the descriptor outputs (standard output among them), then puts every temporary in
  /// place of its target. A failed descriptor write replaces no file.
  void commit();

 private:
  struct Staged {
    std::filesystem::path target;     // as the user named it, for messages
    std::filesystem::path temporary;  // its name beside destination: empty while unnamed
    std::filesystem::path destination;
    int descriptor = -1;  // open until the commit (an unnamed file exists only through it)
    InterruptCleanup cleanup;
  };
  struct DescriptorOutput {
    std::filesystem::path target;
    int descriptor;
    std::vector<std::uint8_t> bytes;
  };
  void create_folders(const std::filesystem::path& target,
                      const std::filesystem::path& destination);
  void stage_to_descriptor(const std::filesystem::path& target, int descriptor,
                           std::span<const std::uint8_t> bytes);
  void write_descriptors();
  void name_unnamed(Staged& staged);

  std::ostream* standard_output_;
  TemporaryFiles temporaries_;
  std::vector<Staged> staged_;
  std::vector<DescriptorOutput> descriptor_outputs_;
  std::vector<std::pair<std::filesystem::path, InterruptCleanup>> created_folders_;
};

/// One file written by the promises above: a transaction of one output.
void write_file_safely(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

/// The bytes of a text, for the functions above.
std::span<const std::uint8_t> bytes_of_text(std::string_view text);

}  // namespace tri
