/// @file
/// Writing output files without ever losing one: every program writes through this file.
///
/// The rules (README, "The raster tool"):
/// - Data goes to a new temporary ".NAME.XXXXXX.tmp" created exclusively (never following a link)
///   in the target's folder, is flushed and synced, and is renamed over the target only when every
///   output of the run is complete. A failure removes the temporaries and leaves every earlier
///   file as it was; an interrupt leaves at worst one such clearly named temporary.
/// - A symbolic link as target is written through: its target file is replaced, the link stays.
/// - A target with several hard links is refused (replacing one name would split them silently).
/// - A target that is not a regular file (folder, device, FIFO, socket) is refused, never
///   replaced; so is a target this user may not write (Permission denied).
/// - An output that is also an input (same device and inode) or two outputs naming one file are
///   refused before any work. "-" means standard output where a program allows it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace tri {

/// An output that cannot be written; what() names the path and the system's reason.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The output name that means standard output.
inline constexpr std::string_view standard_output_name = "-";

/// Checks a run's outputs before any work: throws UsageError for an empty path, two outputs naming
/// one file or an output that is one of the inputs, and OutputError for a target that could not be
/// replaced (see the rules above) or a folder that could not be created.
void check_outputs(std::span<const std::filesystem::path> outputs,
                   std::span<const std::filesystem::path> inputs = {});

/// Checks before any work that files can be written into folder (existing or creatable).
void check_output_folder(const std::filesystem::path& folder);

/// Several outputs that replace their targets together: stage each, then commit. Whatever was
/// staged but not committed is removed when the transaction ends.
class OutputTransaction {
 public:
  /// standard_output receives the outputs named "-"; without it "-" is refused.
  explicit OutputTransaction(std::ostream* standard_output = nullptr)
      : standard_output_(standard_output) {}
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;
  ~OutputTransaction();

  /// Writes bytes to a new temporary beside target (creating missing folders). Throws OutputError.
  void stage(const std::filesystem::path& target, std::span<const std::uint8_t> bytes);
  /// Renames every temporary over its target, then writes the standard-output part.
  void commit();

 private:
  struct Staged {
    std::filesystem::path target;     // as the user named it, for messages
    std::filesystem::path temporary;  // beside destination
    std::filesystem::path destination;
  };
  std::ostream* standard_output_;
  std::vector<Staged> staged_;
  std::vector<std::uint8_t> standard_output_bytes_;
  bool standard_output_staged_ = false;
};

/// One file written by the rules above: a transaction of one output.
void write_file_safely(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);

/// The bytes of a text, for the functions above.
std::span<const std::uint8_t> bytes_of_text(std::string_view text);

}  // namespace tri
