#include "common/output_files.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
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

fs::path folder_of(const fs::path& path) {
  return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

// The descriptor a name in /proc/self/fd (also reached as /dev/fd/N or /proc/PID/fd/N with our
// PID) stands for: such a name is a descriptor, and the file behind it must not be replaced.
std::optional<int> descriptor_named_by(const fs::path& path) {
  const std::string name = path.filename().string();
  if (name.empty() || name.size() > 9 ||
      !std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  std::error_code error;
  const fs::path folder = fs::canonical(folder_of(path), error);
  if (error || folder != fs::path("/proc") / std::to_string(::getpid()) / "fd") {
    return std::nullopt;
  }
  return std::stoi(name);
}

// Where an output goes: a descriptor, or the file left when every symbolic link is followed.
struct Target {
  std::optional<int> descriptor;
  fs::path file;
};

// The kernel's protected_symlinks check, applied because we resolve links ourselves: in a sticky
// world-writable folder only a link owned by the folder's owner or by this user is followed.
void check_link_may_be_followed(const fs::path& shown, const fs::path& link,
                                const struct stat& link_info) {
  const auto folder = status_of(folder_of(link), true);
  if (!folder || (folder->st_mode & S_ISVTX) == 0 || (folder->st_mode & S_IWOTH) == 0) return;
  if (link_info.st_uid == folder->st_uid || link_info.st_uid == ::geteuid()) return;
  fail(shown, "it is a symbolic link in the sticky world-writable folder " +
                  folder_of(link).string() +
                  " owned by neither the folder's owner nor you, which is never followed");
}

Target resolve(const fs::path& target) {
  if (target == standard_output_name) return {STDOUT_FILENO, {}};
  if (!target.has_filename() || target.filename() == "." || target.filename() == "..") {
    throw UsageError("the output " + target.string() +
                     " names a folder; an output is a file (drop the trailing slash)");
  }
  fs::path current = target;
  constexpr int most_links = 40;  // as the kernel's ELOOP limit
  for (int links = 0; links <= most_links; ++links) {
    if (const auto descriptor = descriptor_named_by(current)) return {*descriptor, {}};
    const auto own = status_of(current, false);
    if (!own) {
      if (errno != ENOENT) fail_with_errno(target, errno);
      if (links > 0)
        fail(target, "a symbolic link to " + current.string() + ", which does not exist");
      return {std::nullopt, current};
    }
    if (!S_ISLNK(own->st_mode)) return {std::nullopt, current};
    check_link_may_be_followed(target, current, *own);
    std::error_code error;
    const fs::path next = fs::read_symlink(current, error);
    if (error)
      fail(target, "cannot read the symbolic link " + current.string() + ": " + error.message());
    current = next.is_absolute() ? next : folder_of(current) / next;
  }
  fail_with_errno(target, ELOOP);
}

// The file a target names once links are followed: the target itself when it does not exist yet.
// Throws OutputError when the existing file may not be replaced by the promises of the header.
fs::path destination_of(const fs::path& target, const fs::path& resolved) {
  const auto info = status_of(resolved, true);
  if (!info) {
    if (errno == ENOENT) return resolved;
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
  if (::access(resolved.c_str(), W_OK) != 0) fail_with_errno(target, errno);
  return resolved;
}

// A descriptor output must be open for writing; it is written, never replaced.
void check_descriptor(const fs::path& target, int descriptor) {
  const int flags = ::fcntl(descriptor, F_GETFL);
  if (flags < 0) fail(target, "descriptor " + std::to_string(descriptor) + " is not open");
  if ((flags & O_ACCMODE) == O_RDONLY) {
    fail(target, "descriptor " + std::to_string(descriptor) + " is open for reading only");
  }
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

// Tries fresh temporary names beside destination until make(name) succeeds; make returns false
// with errno EEXIST when the name is taken.
template <class Make>
fs::path at_fresh_temporary_name(const fs::path& target, const fs::path& destination, Make make) {
  std::mt19937_64 random(std::random_device{}());
  for (int attempt = 0;; ++attempt) {
    fs::path temporary = temporary_name(destination, random);
    if (make(temporary)) return temporary;
    if (errno != EEXIST || attempt == 100) fail_with_errno(target, errno);
  }
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
  const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (descriptor < 0) return;
  ::fsync(descriptor);
  ::close(descriptor);
}

// The replaced file's owner, group and permission bits on the new one, as far as this user may
// set them; setuid, setgid and sticky bits are never copied onto new content.
void keep_owner_and_mode(int descriptor, const struct stat& replaced) {
  if (::fchown(descriptor, replaced.st_uid, replaced.st_gid) != 0) {
    static_cast<void>(::fchown(descriptor, static_cast<uid_t>(-1), replaced.st_gid));
  }
  ::fchmod(descriptor, replaced.st_mode & 0777);
}

// Test hook: with TUTORIAL_TEST_STOP_AFTER_EACH_OUTPUT=1 the process stops itself (SIGSTOP) after
// each staged output, so a test can interrupt a run at a known point between its outputs.
void stop_if_asked_by_a_test() {
  const char* stop = std::getenv("TUTORIAL_TEST_STOP_AFTER_EACH_OUTPUT");
  if (stop != nullptr && std::string_view(stop) == "1") ::raise(SIGSTOP);
}

// What makes two paths one file: a descriptor, device and inode when it exists, else its
// absolute name.
struct FileKey {
  enum Kind { descriptor, existing, missing } kind = missing;
  dev_t device = 0;
  ino_t inode = 0;
  fs::path name;
  bool operator==(const FileKey& other) const {
    if (kind != other.kind) return false;
    if (kind == missing) return name == other.name;
    return device == other.device && inode == other.inode;
  }
};

FileKey key_of(const fs::path& path) {
  FileKey key;
  if (const auto info = status_of(path, true)) {
    key.kind = FileKey::existing;
    key.device = info->st_dev;
    key.inode = info->st_ino;
  } else {
    std::error_code error;
    key.name = fs::weakly_canonical(fs::absolute(path, error), error);
    if (error) key.name = fs::absolute(path, error).lexically_normal();
  }
  return key;
}

// Exclusive flock()s on the folders of a commit's files, taken in one order (device, inode) so
// two runs never wait for each other in a circle; released when the object goes.
class FolderLocks {
 public:
  explicit FolderLocks(const std::vector<fs::path>& folders) {
    std::vector<std::pair<std::pair<dev_t, ino_t>, int>> opened;
    for (const fs::path& folder : folders) {
      const int descriptor = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      if (descriptor < 0) continue;  // an unreadable folder goes unlocked: best effort
      struct stat info {};
      ::fstat(descriptor, &info);
      const auto key = std::make_pair(info.st_dev, info.st_ino);
      const bool seen = std::any_of(opened.begin(), opened.end(),
                                    [&](const auto& other) { return other.first == key; });
      if (seen) {
        ::close(descriptor);
        continue;
      }
      opened.emplace_back(key, descriptor);
    }
    std::sort(opened.begin(), opened.end());
    for (const auto& [key, descriptor] : opened) {
      while (::flock(descriptor, LOCK_EX) != 0 && errno == EINTR) {
      }
      descriptors_.push_back(descriptor);
    }
  }
  FolderLocks(const FolderLocks&) = delete;
  FolderLocks& operator=(const FolderLocks&) = delete;
  ~FolderLocks() {
    for (const int descriptor : descriptors_) ::close(descriptor);
  }

 private:
  std::vector<int> descriptors_;
};

}  // namespace

std::optional<int> output_descriptor(const fs::path& output) {
  if (output.empty()) return std::nullopt;
  return resolve(output).descriptor;
}

void check_outputs(std::span<const fs::path> outputs, std::span<const fs::path> inputs) {
  std::vector<FileKey> keys;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const fs::path& output = outputs[i];
    if (output.empty()) throw UsageError("an output path is empty");
    const Target target = resolve(output);
    if (target.descriptor) {
      check_descriptor(output, *target.descriptor);
      keys.push_back({FileKey::descriptor, 0, static_cast<ino_t>(*target.descriptor), {}});
    } else {
      keys.push_back(key_of(output));
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (keys[j] == keys[i]) {
        throw UsageError("two outputs name one file: " + outputs[j].string() + " and " +
                         output.string());
      }
    }
    if (target.descriptor) continue;
    for (const fs::path& input : inputs) {
      const FileKey input_key = key_of(input);
      if (input_key.kind == FileKey::existing && input_key == keys[i]) {
        throw UsageError("the output " + output.string() + " is the input " + input.string() +
                         "; choose another output name");
      }
    }
    const fs::path destination = destination_of(output, target.file);
    check_folder_writable(output, destination.parent_path());
  }
}

void check_output_folder(const fs::path& folder) {
  if (folder.empty()) throw UsageError("the output folder is empty");
  check_folder_writable(folder, folder);
}

OutputTransaction::~OutputTransaction() {
  for (Staged& staged : staged_) {
    if (staged.descriptor >= 0) ::close(staged.descriptor);
    if (!staged.temporary.empty()) ::unlink(staged.temporary.c_str());
  }
  // Folders made for this run's outputs go when the run failed; rmdir keeps any that filled.
  for (auto folder = created_folders_.rbegin(); folder != created_folders_.rend(); ++folder) {
    ::rmdir(folder->first.c_str());
  }
}

// Makes the missing folders above destination one by one, so that a failed run removes exactly
// those it made.
void OutputTransaction::create_folders(const fs::path& target, const fs::path& destination) {
  std::vector<fs::path> missing;
  for (fs::path folder = destination.parent_path(); !folder.empty() && !fs::exists(folder);
       folder = folder.parent_path()) {
    missing.push_back(folder);
    if (!folder.has_relative_path()) break;
  }
  for (auto folder = missing.rbegin(); folder != missing.rend(); ++folder) {
    if (::mkdir(folder->c_str(), 0777) != 0 && errno != EEXIST) {
      fail(target, "cannot create folder " + folder->string() + ": " + std::strerror(errno));
    }
    created_folders_.emplace_back(*folder, InterruptCleanup(*folder, LeftoverKind::folder));
  }
}

void OutputTransaction::stage(const fs::path& target, std::span<const std::uint8_t> bytes) {
  if (target.empty()) throw OutputError("cannot write an output with an empty path");
  const Target resolved = [&] {
    try {
      return resolve(target);
    } catch (const UsageError& e) {
      throw OutputError(e.what());
    }
  }();
  if (resolved.descriptor) {
    stage_to_descriptor(target, *resolved.descriptor, bytes);
    stop_if_asked_by_a_test();
    return;
  }
  const fs::path destination = destination_of(target, resolved.file);
  check_folder_writable(target, destination.parent_path());
  create_folders(target, destination);

  Staged staged{target, {}, destination, -1, {}};
  const fs::path folder = folder_of(destination);
  // 0666 less the umask, as for any new file. An unnamed file (O_TMPFILE) leaves nothing behind
  // whatever ends the run; elsewhere a named one is created exclusively, never through a link.
  if (temporaries_ == TemporaryFiles::unnamed_where_supported) {
    staged.descriptor = ::open(folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (staged.descriptor < 0 && errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) {
      fail_with_errno(target, errno);
    }
  }
  if (staged.descriptor < 0) {
    staged.temporary = at_fresh_temporary_name(target, destination, [&](const fs::path& name) {
      staged.descriptor =
          ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
      return staged.descriptor >= 0;
    });
    staged.cleanup = InterruptCleanup(staged.temporary, LeftoverKind::file);
  }
  staged_.push_back(std::move(staged));
  const int descriptor = staged_.back().descriptor;
  if (const auto existing = status_of(destination, true))
    keep_owner_and_mode(descriptor, *existing);
  write_all(descriptor, bytes, target);
  if (::fsync(descriptor) != 0) fail_with_errno(target, errno);
  stop_if_asked_by_a_test();
}

void OutputTransaction::stage_to_descriptor(const fs::path& target, int descriptor,
                                            std::span<const std::uint8_t> bytes) {
  if (descriptor == STDOUT_FILENO && standard_output_ == nullptr) {
    fail(target, "this output cannot go to standard output");
  }
  check_descriptor(target, descriptor);
  DescriptorOutput& output = [&]() -> DescriptorOutput& {
    for (DescriptorOutput& other : descriptor_outputs_) {
      if (other.descriptor == descriptor) return other;
    }
    return descriptor_outputs_.emplace_back(DescriptorOutput{target, descriptor, {}});
  }();
  output.bytes.insert(output.bytes.end(), bytes.begin(), bytes.end());
}

// The descriptors first: a failed write there (a full disk, a closed pipe) leaves every file as
// it was, while a file's rename, done after, practically never fails.
void OutputTransaction::write_descriptors() {
  for (DescriptorOutput& output : descriptor_outputs_) {
    if (output.descriptor == STDOUT_FILENO) {
      errno = 0;
      standard_output_->write(reinterpret_cast<const char*>(output.bytes.data()),
                              static_cast<std::streamsize>(output.bytes.size()));
      standard_output_->flush();
      if (!*standard_output_) {
        const int error = errno;
        throw OutputError(std::string("cannot write the results to standard output: ") +
                          (error != 0 ? std::strerror(error) : "write failed"));
      }
    } else {
      write_all(output.descriptor, output.bytes, output.target);
    }
  }
  descriptor_outputs_.clear();
}

// Gives an unnamed temporary a fresh name beside its destination: linkat() cannot replace a file,
// so the rename that follows does.
void OutputTransaction::name_unnamed(Staged& staged) {
  const std::string by_proc = "/proc/self/fd/" + std::to_string(staged.descriptor);
  staged.temporary =
      at_fresh_temporary_name(staged.target, staged.destination, [&](const fs::path& name) {
        return ::linkat(AT_FDCWD, by_proc.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) ==
                   0 ||
               (errno == ENOENT &&  // no /proc: a privileged process may link the descriptor
                ::linkat(staged.descriptor, "", AT_FDCWD, name.c_str(), AT_EMPTY_PATH) == 0);
      });
  // Registered once it is ours: a name taken by another file must never be removed.
  staged.cleanup = InterruptCleanup(staged.temporary, LeftoverKind::file);
}

void OutputTransaction::commit() {
  write_descriptors();
  std::vector<fs::path> folders;
  for (const Staged& staged : staged_) folders.push_back(folder_of(staged.destination));
  const FolderLocks locks(folders);  // a parallel run commits its set before or after ours
  while (!staged_.empty()) {
    Staged& staged = staged_.front();
    if (staged.temporary.empty()) name_unnamed(staged);
    if (::rename(staged.temporary.c_str(), staged.destination.c_str()) != 0) {
      fail_with_errno(staged.target, errno);
    }
    staged.cleanup.release();
    staged.temporary.clear();
    ::close(staged.descriptor);
    staged.descriptor = -1;
    sync_folder(folder_of(staged.destination));
    staged_.erase(staged_.begin());
  }
  created_folders_.clear();  // they hold the committed files now
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
