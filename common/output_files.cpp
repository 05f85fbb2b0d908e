#include "common/output_files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <optional>
#include <random>
#include <string>

#include "common/cli.hpp"

namespace tri {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& path, const std::string& reason) {
  throw OutputError("cannot write " + path.string() + ": " + reason);
}

[[noreturn]] void fail_with_errno(const fs::path& path, int error) {
  fail(path, std::strerror(error));
}

std::optional<struct stat> status_of(const fs::path& path, bool follow_links) {
  struct stat info {};
  const int result = follow_links ? ::stat(path.c_str(), &info) : ::lstat(path.c_str(), &info);
  if (result != 0) return std::nullopt;
  return info;
}

const char* kind_of(mode_t mode) {
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// The file a target names once links are followed: the target itself when it does not exist yet.
// Throws OutputError when the existing file may not be replaced by the rules of the header.
fs::path destination_of(const fs::path& target) {
  const auto own = status_of(target, false);
  if (!own) {
    if (errno == ENOENT) return target;
    fail_with_errno(target, errno);
  }
  fs::path destination = target;
  if (S_ISLNK(own->st_mode)) {
    std::error_code error;
    destination = fs::canonical(target, error);
    if (error) fail(target, "a symbolic link whose target cannot be resolved: " + error.message());
  }
  const auto info = status_of(destination, true);
  if (!info) {
    if (errno == ENOENT) return destination;
    fail_with_errno(target, errno);
  }
  if (S_ISDIR(info->st_mode)) fail_with_errno(target, EISDIR);
  if (!S_ISREG(info->st_mode)) {
    fail(target, std::string("it is ") + kind_of(info->st_mode) + ", which is never replaced");
  }
  if (info->st_nlink > 1) {
    fail(target, "it has " + std::to_string(info->st_nlink) +
                     " hard links, which replacing it would split; remove it first");
  }
  if (::access(destination.c_str(), W_OK) != 0) fail_with_errno(target, errno);
  return destination;
}

// The folder a new file would go into, checked (or its nearest existing ancestor) for writing.
void check_folder_writable(const fs::path& shown, const fs::path& folder) {
  fs::path existing = folder.empty() ? fs::path(".") : folder;
  while (true) {
    const auto info = status_of(existing, true);
    if (info) {
      if (!S_ISDIR(info->st_mode)) fail(shown, existing.string() + " is not a folder");
      if (::access(existing.c_str(), W_OK | X_OK) != 0) {
        fail(shown, "folder " + existing.string() + ": " + std::strerror(errno));
      }
      return;
    }
    if (errno != ENOENT) fail(shown, "folder " + existing.string() + ": " + std::strerror(errno));
    if (!existing.has_relative_path() || !existing.has_parent_path()) return;
    const fs::path parent = existing.parent_path();
    existing = parent.empty() ? fs::path(".") : parent;
  }
}

// The name of a temporary for destination: ".NAME.XXXXXX.tmp", NAME cut so the whole fits 255.
fs::path temporary_name(const fs::path& destination, std::mt19937_64& random) {
  constexpr std::size_t longest_name = 255;
  constexpr std::string_view letters =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::string name = destination.filename().string();
  constexpr std::size_t decoration = 1 + 1 + 6 + 4;  // ".", ".", XXXXXX, ".tmp"
  if (name.size() > longest_name - decoration) name.resize(longest_name - decoration);
  std::string suffix(6, 'x');
  for (char& c : suffix) c = letters[random() % letters.size()];
  return destination.parent_path() / ("." + name + "." + suffix + ".tmp");
}

void write_all(int descriptor, std::span<const std::uint8_t> bytes, const fs::path& shown) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t written = ::write(descriptor, bytes.data() + done, bytes.size() - done);
    if (written < 0) {
      if (errno == EINTR) continue;
      fail_with_errno(shown, errno);
    }
    done += static_cast<std::size_t>(written);
  }
}

// Sync a folder so the renames in it survive a crash; best effort (some file systems refuse).
void sync_folder(const fs::path& folder) {
  const int descriptor =
      ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (descriptor < 0) return;
  ::fsync(descriptor);
  ::close(descriptor);
}

// What makes two paths one file: device and inode when it exists, else its absolute name.
struct FileKey {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  fs::path name;
  bool operator==(const FileKey& other) const {
    if (exists != other.exists) return false;
    return exists ? device == other.device && inode == other.inode : name == other.name;
  }
};

FileKey key_of(const fs::path& path) {
  FileKey key;
  if (const auto info = status_of(path, true)) {
    key.exists = true;
    key.device = info->st_dev;
    key.inode = info->st_ino;
  } else {
    std::error_code error;
    key.name = fs::weakly_canonical(fs::absolute(path, error), error);
    if (error) key.name = fs::absolute(path, error).lexically_normal();
  }
  return key;
}

}  // namespace

void check_outputs(std::span<const fs::path> outputs, std::span<const fs::path> inputs) {
  std::vector<FileKey> keys;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const fs::path& output = outputs[i];
    if (output.empty()) throw UsageError("an output path is empty");
    const bool is_standard_output = output == standard_output_name;
    keys.push_back(is_standard_output ? FileKey{false, 0, 0, "-"} : key_of(output));
    for (std::size_t j = 0; j < i; ++j) {
      if (keys[j] == keys[i]) {
        throw UsageError("two outputs name one file: " + outputs[j].string() + " and " +
                         output.string());
      }
    }
    if (is_standard_output) continue;
    for (const fs::path& input : inputs) {
      if (key_of(input).exists && key_of(input) == keys[i]) {
        throw UsageError("the output " + output.string() + " is the input " + input.string() +
                         "; choose another output name");
      }
    }
    const fs::path destination = destination_of(output);
    check_folder_writable(output, destination.parent_path());
  }
}

void check_output_folder(const fs::path& folder) {
  if (folder.empty()) throw UsageError("the output folder is empty");
  check_folder_writable(folder, folder);
}

OutputTransaction::~OutputTransaction() {
  for (const Staged& staged : staged_) ::unlink(staged.temporary.c_str());
}

void OutputTransaction::stage(const fs::path& target, std::span<const std::uint8_t> bytes) {
  if (target.empty()) throw OutputError("cannot write an output with an empty path");
  if (target == standard_output_name) {
    if (standard_output_ == nullptr) fail(target, "this output cannot go to standard output");
    standard_output_bytes_.insert(standard_output_bytes_.end(), bytes.begin(), bytes.end());
    standard_output_staged_ = true;
    return;
  }
  const fs::path destination = destination_of(target);
  check_folder_writable(target, destination.parent_path());
  if (destination.has_parent_path()) {
    std::error_code error;
    fs::create_directories(destination.parent_path(), error);
    if (error)
      fail(target,
           "cannot create folder " + destination.parent_path().string() + ": " + error.message());
  }
  std::mt19937_64 random(std::random_device{}());
  int descriptor = -1;
  fs::path temporary;
  for (int attempt = 0; descriptor < 0; ++attempt) {
    temporary = temporary_name(destination, random);
    // 0666 less the umask, as for any new file; O_EXCL|O_NOFOLLOW never opens what is there.
    descriptor =
        ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (descriptor < 0 && (errno != EEXIST || attempt == 100)) fail_with_errno(target, errno);
  }
  staged_.push_back({target, temporary, destination});
  if (const auto existing = status_of(destination, true)) {
    ::fchmod(descriptor, existing->st_mode & 07777);  // keep the target's permissions
  }
  try {
    write_all(descriptor, bytes, target);
    if (::fsync(descriptor) != 0) fail_with_errno(target, errno);
  } catch (...) {
    ::close(descriptor);
    throw;
  }
  if (::close(descriptor) != 0) fail_with_errno(target, errno);
}

void OutputTransaction::commit() {
  while (!staged_.empty()) {
    const Staged& staged = staged_.front();
    if (::rename(staged.temporary.c_str(), staged.destination.c_str()) != 0) {
      fail_with_errno(staged.target, errno);
    }
    sync_folder(staged.destination.parent_path());
    staged_.erase(staged_.begin());
  }
  if (standard_output_staged_) {
    standard_output_->write(reinterpret_cast<const char*>(standard_output_bytes_.data()),
                            static_cast<std::streamsize>(standard_output_bytes_.size()));
    standard_output_->flush();
    if (!*standard_output_) fail(standard_output_name, "writing to standard output failed");
    standard_output_staged_ = false;
  }
}

void write_file_safely(const fs::path& path, std::span<const std::uint8_t> bytes) {
  OutputTransaction transaction;
  transaction.stage(path, bytes);
  transaction.commit();
}

std::span<const std::uint8_t> bytes_of_text(std::string_view text) {
  return {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()};
}

}  // namespace tri
