#include "common/output_files.hpp"

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "common/cli.hpp"
#include "tests/support/scratch_folder.hpp"

namespace tri {
namespace {

namespace fs = std::filesystem;
using testing::has_unnamed_temporaries;
using testing::names_in;
using testing::read_text;
using testing::write_text;

bool running_as_root() {
  return ::geteuid() == 0;
}

struct stat status_of(const fs::path& path) {
  struct stat info {};
  REQUIRE(::lstat(path.c_str(), &info) == 0);
  return info;
}

// The pair most tests write: a.txt replaced, b.txt new.
void stage_new_a_and_b(OutputTransaction& outputs, const fs::path& folder) {
  outputs.stage(folder / "a.txt", bytes_of_text("new a"));
  outputs.stage(folder / "b.txt", bytes_of_text("new b"));
}

// After the pair's commit the folder holds both new files and nothing else.
void check_holds_new_a_and_b(const fs::path& folder) {
  CHECK(read_text(folder / "a.txt") == "new a");
  CHECK(read_text(folder / "b.txt") == "new b");
  CHECK(names_in(folder) == std::vector<std::string>{"a.txt", "b.txt"});
}

// Runs body in a child process whose signals are at their defaults, as in a program (Catch2
// handles them in the test process), and returns the signal that ended it (0: it exited).
template <class Body>
int signal_ending(Body body) {
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXFSZ}) {
      ::signal(signal_number, SIG_DFL);
    }
    body();
    ::_exit(0);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
}

}  // namespace

TEST_CASE("A failing second output leaves the first output's earlier file exactly as it was",
          "[common][output_files]") {
  const testing::ScratchFolder scratch("second_fails");
  const fs::path& folder = scratch.path();
  write_text(folder / "picture.png", "the earlier picture");
  fs::create_directory(folder / "counts.pgm");  // a folder: this output cannot be written
  {
    OutputTransaction outputs;
    outputs.stage(folder / "picture.png", bytes_of_text("the new picture"));
    CHECK_THROWS_WITH(
        outputs.stage(folder / "counts.pgm", bytes_of_text("counts")),
        Catch::Contains((folder / "counts.pgm").string()) && Catch::Contains("Is a directory"));
  }
  CHECK(read_text(folder / "picture.png") == "the earlier picture");
  CHECK(names_in(folder) == std::vector<std::string>{"counts.pgm", "picture.png"});
}

TEST_CASE("Staged outputs replace nothing and leave nothing behind until they are committed",
          "[common][output_files]") {
  const testing::ScratchFolder scratch("uncommitted");
  const fs::path& folder = scratch.path();
  write_text(folder / "a.txt", "old a");
  {
    OutputTransaction outputs;
    stage_new_a_and_b(outputs, folder);
    CHECK(read_text(folder / "a.txt") == "old a");
    CHECK_FALSE(fs::exists(folder / "b.txt"));
  }
  CHECK(names_in(folder) == std::vector<std::string>{"a.txt"});
  {
    OutputTransaction outputs;
    stage_new_a_and_b(outputs, folder);
    outputs.commit();
  }
  check_holds_new_a_and_b(folder);
}

TEST_CASE("A named temporary is a new regular file named .NAME.XXXXXX.tmp beside the output",
          "[common][output_files]") {
  const testing::ScratchFolder scratch("temporary_name");
  const fs::path& folder = scratch.path();
  OutputTransaction outputs(nullptr, TemporaryFiles::named);
  outputs.stage(folder / "render.png", bytes_of_text("png"));
  const auto names = names_in(folder);
  REQUIRE(names.size() == 1);
  CHECK(std::regex_match(names[0], std::regex(R"(\.render\.png\.[A-Za-z0-9]{6}\.tmp)")));
  CHECK(fs::is_regular_file(fs::symlink_status(folder / names[0])));
  CHECK(read_text(folder / names[0]) == "png");
}

TEST_CASE("Symlinks planted at temporary-looking names beside the output are not followed",
          "[common][output_files][links]") {
  const testing::ScratchFolder scratch("planted_links");
  const fs::path& folder = scratch.path();
  write_text(folder / "victim", "precious");
  for (const char* name : {"render.png.tmp", ".render.png.tmp", ".render.png.tmp.tmp"}) {
    fs::create_symlink(folder / "victim", folder / name);
  }
  write_file_safely(folder / "render.png", bytes_of_text("png"));
  CHECK(read_text(folder / "victim") == "precious");
  CHECK(read_text(folder / "render.png") == "png");
  CHECK(fs::is_symlink(folder / "render.png.tmp"));
  CHECK(fs::is_symlink(folder / ".render.png.tmp"));
  CHECK(names_in(folder).size() == 5);  // victim, three links, render.png: no temporary left
}

TEST_CASE("A symlinked output is written through: the link stays, its file gets the new bytes",
          "[common][output_files][links]") {
  const testing::ScratchFolder scratch("write_through");
  const fs::path& folder = scratch.path();
  fs::create_directory(folder / "real");
  write_text(folder / "real" / "picture.png", "old");
  fs::create_symlink("real/picture.png", folder / "link.png");
  write_file_safely(folder / "link.png", bytes_of_text("new"));
  CHECK(fs::is_symlink(folder / "link.png"));
  CHECK(read_text(folder / "real" / "picture.png") == "new");
  CHECK(names_in(folder / "real") == std::vector<std::string>{"picture.png"});
}

TEST_CASE("An output with several hard links is refused and every link keeps its content",
          "[common][output_files][links]") {
  const testing::ScratchFolder scratch("hard_links");
  const fs::path& folder = scratch.path();
  write_text(folder / "a.png", "shared");
  fs::create_hard_link(folder / "a.png", folder / "b.png");
  CHECK_THROWS_WITH(write_file_safely(folder / "a.png", bytes_of_text("new")),
                    Catch::Contains("hard links"));
  CHECK(read_text(folder / "a.png") == "shared");
  CHECK(fs::hard_link_count(folder / "b.png") == 2);
}

TEST_CASE("An output that is an input is refused, also through a hard link or a symlink",
          "[common][output_files][identity]") {
  const testing::ScratchFolder scratch("input_as_output");
  const fs::path& folder = scratch.path();
  write_text(folder / "s.scene", "canvas 4 4\n");
  fs::create_hard_link(folder / "s.scene", folder / "hard.scene");
  fs::create_symlink(folder / "s.scene", folder / "soft.scene");
  const std::vector<fs::path> inputs{folder / "s.scene"};
  for (const char* name : {"s.scene", "hard.scene", "soft.scene"}) {
    const std::vector<fs::path> outputs{folder / name};
    CHECK_THROWS_AS(check_outputs(outputs, inputs), UsageError);
    CHECK_THROWS_WITH(check_outputs(outputs, inputs), Catch::Contains("is the input"));
  }
  CHECK(read_text(folder / "s.scene") == "canvas 4 4\n");
  const std::vector<fs::path> other{folder / "picture.png"};
  CHECK_NOTHROW(check_outputs(other, inputs));
}

TEST_CASE("Two outputs naming one file are refused, whether it exists or not",
          "[common][output_files][identity]") {
  const testing::ScratchFolder scratch("same_file");
  const fs::path& folder = scratch.path();
  const std::vector<fs::path> new_file{folder / "x.png", folder / "." / "x.png"};
  CHECK_THROWS_WITH(check_outputs(new_file), Catch::Contains("two outputs name one file"));
  write_text(folder / "y.png", "old");
  fs::create_symlink("y.png", folder / "alias.png");
  const std::vector<fs::path> linked{folder / "y.png", folder / "alias.png"};
  CHECK_THROWS_AS(check_outputs(linked), UsageError);
  const std::vector<fs::path> twice_standard_output{"-", "-"};
  CHECK_THROWS_AS(check_outputs(twice_standard_output), UsageError);
  const std::vector<fs::path> distinct{folder / "x.png", folder / "y.png", "-"};
  CHECK_NOTHROW(check_outputs(distinct));
}

TEST_CASE("An empty output path is refused as a usage error", "[common][output_files]") {
  const std::vector<fs::path> outputs{""};
  CHECK_THROWS_AS(check_outputs(outputs), UsageError);
  CHECK_THROWS_AS(write_file_safely("", bytes_of_text("x")), OutputError);
  CHECK_THROWS_AS(check_output_folder(""), UsageError);
}

TEST_CASE("A device or a FIFO as output is refused with a reason and never replaced",
          "[common][output_files][special]") {
  const std::vector<fs::path> device{"/dev/null"};
  CHECK_THROWS_WITH(check_outputs(device), Catch::Contains("character device"));
  CHECK_THROWS_WITH(write_file_safely("/dev/null", bytes_of_text("x")),
                    Catch::Contains("/dev/null") && Catch::Contains("never replaced"));
  CHECK(fs::is_character_file("/dev/null"));

  const testing::ScratchFolder scratch("fifo");
  const fs::path& folder = scratch.path();
  REQUIRE(::mkfifo((folder / "pipe").c_str(), 0666) == 0);
  CHECK_THROWS_WITH(write_file_safely(folder / "pipe", bytes_of_text("x")),
                    Catch::Contains("FIFO"));
  CHECK(fs::is_fifo(folder / "pipe"));
  CHECK(names_in(folder) == std::vector<std::string>{"pipe"});
}

TEST_CASE("A read-only existing output is refused with Permission denied and kept",
          "[common][output_files][permissions]") {
  if (running_as_root()) {
    WARN("skipped: root may write any file, so a read-only file is no obstacle to root");
    SUCCEED();
    return;
  }
  const testing::ScratchFolder scratch("read_only");
  const fs::path& folder = scratch.path();
  write_text(folder / "keep.png", "keep me");
  fs::permissions(folder / "keep.png", fs::perms::owner_read | fs::perms::group_read);
  const std::vector<fs::path> outputs{folder / "keep.png"};
  CHECK_THROWS_WITH(check_outputs(outputs), Catch::Contains("Permission denied"));
  CHECK_THROWS_WITH(write_file_safely(folder / "keep.png", bytes_of_text("x")),
                    Catch::Contains("Permission denied"));
  CHECK(read_text(folder / "keep.png") == "keep me");
  fs::permissions(folder / "keep.png", fs::perms::owner_all);
}

TEST_CASE("A new output gets mode 0666 less the umask, a replaced one keeps its mode",
          "[common][output_files]") {
  const testing::ScratchFolder scratch("modes");
  const fs::path& folder = scratch.path();
  const mode_t previous = ::umask(022);
  write_file_safely(folder / "new.txt", bytes_of_text("x"));
  ::umask(previous);
  struct stat info {};
  REQUIRE(::stat((folder / "new.txt").c_str(), &info) == 0);
  CHECK((info.st_mode & 0777) == 0644);

  write_text(folder / "script.sh", "old");
  fs::permissions(folder / "script.sh", static_cast<fs::perms>(0750));
  write_file_safely(folder / "script.sh", bytes_of_text("new"));
  REQUIRE(::stat((folder / "script.sh").c_str(), &info) == 0);
  CHECK((info.st_mode & 0777) == 0750);
}

TEST_CASE("An output name of 255 characters is written, its temporary name is shortened",
          "[common][output_files]") {
  const testing::ScratchFolder scratch("long_name");
  const fs::path& folder = scratch.path();
  const std::string name(255, 'n');
  write_file_safely(folder / name, bytes_of_text("long"));
  CHECK(read_text(folder / name) == "long");
  CHECK(names_in(folder) == std::vector<std::string>{name});
}

TEST_CASE("An output below a regular file fails, names the system's reason and writes nothing",
          "[common][output_files]") {
  const testing::ScratchFolder scratch("below_file");
  const fs::path& folder = scratch.path();
  write_text(folder / "blocker", "a file");
  const std::vector<fs::path> outputs{folder / "blocker" / "sub" / "x.png"};
  CHECK_THROWS_WITH(check_outputs(outputs), Catch::Contains("Not a directory"));
  CHECK_THROWS_WITH(check_output_folder(folder / "blocker"), Catch::Contains("is not a folder"));
  CHECK_NOTHROW(check_output_folder(folder / "new" / "folder"));
  CHECK_FALSE(fs::exists(folder / "new"));  // checking creates nothing
  CHECK(names_in(folder) == std::vector<std::string>{"blocker"});
}

TEST_CASE("The output - goes to the given standard output, and is refused without one",
          "[common][output_files][standard_output]") {
  std::ostringstream standard_output;
  {
    OutputTransaction outputs(&standard_output);
    outputs.stage("-", bytes_of_text("bytes"));
    CHECK(standard_output.str().empty());
    outputs.commit();
  }
  CHECK(standard_output.str() == "bytes");
  CHECK_THROWS_AS(write_file_safely("-", bytes_of_text("x")), OutputError);
  CHECK_FALSE(fs::exists("-"));
}

TEST_CASE("Staged outputs leave no name in their folder where unnamed temporaries exist",
          "[common][output_files][interrupts]") {
  const testing::ScratchFolder scratch("unnamed");
  const fs::path& folder = scratch.path();
  if (!has_unnamed_temporaries(folder)) {
    WARN("skipped: the file system of " << folder << " has no O_TMPFILE");
    return;
  }
  write_text(folder / "a.txt", "old a");
  OutputTransaction outputs;
  stage_new_a_and_b(outputs, folder);
  CHECK(names_in(folder) == std::vector<std::string>{"a.txt"});
  outputs.commit();
  check_holds_new_a_and_b(folder);
}

TEST_CASE("A signal while named temporaries are staged removes them and the folders made for them",
          "[common][output_files][interrupts]") {
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGXFSZ}) {
    const testing::ScratchFolder scratch("signalled");
    const fs::path& folder = scratch.path();
    write_text(folder / "a.txt", "old a");
    const int ended_by = signal_ending([&] {
      OutputTransaction outputs(nullptr, TemporaryFiles::named);
      outputs.stage(folder / "a.txt", bytes_of_text("new a"));
      outputs.stage(folder / "made" / "deeper" / "b.txt", bytes_of_text("new b"));
      ::raise(signal_number);
    });
    CHECK(ended_by == signal_number);
    CHECK(names_in(folder) == std::vector<std::string>{"a.txt"});
    CHECK(read_text(folder / "a.txt") == "old a");
  }
}

TEST_CASE("A failed run removes the folders it made for its outputs and keeps those it found",
          "[common][output_files]") {
  const testing::ScratchFolder scratch("made_folders");
  const fs::path& folder = scratch.path();
  fs::create_directory(folder / "found");
  fs::create_directory(folder / "taken");
  {
    OutputTransaction outputs;
    outputs.stage(folder / "found" / "made" / "deeper" / "a.txt", bytes_of_text("a"));
    CHECK(fs::is_directory(folder / "found" / "made" / "deeper"));
    CHECK_THROWS_AS(outputs.stage(folder / "taken", bytes_of_text("b")), OutputError);
  }
  CHECK(names_in(folder) == std::vector<std::string>{"found", "taken"});
  CHECK(names_in(folder / "found").empty());
  write_file_safely(folder / "kept" / "a.txt", bytes_of_text("a"));  // a committed run keeps it
  CHECK(read_text(folder / "kept" / "a.txt") == "a");
}

TEST_CASE("An output name ending in a slash is a usage error and creates nothing",
          "[common][output_files]") {
  const testing::ScratchFolder scratch("trailing_slash");
  const fs::path& folder = scratch.path();
  for (const fs::path& name : {folder / "x.png/", folder / "x.png" / ".", folder / "x" / ".."}) {
    const std::vector<fs::path> outputs{name};
    CHECK_THROWS_AS(check_outputs(outputs), UsageError);
    CHECK_THROWS_WITH(check_outputs(outputs), Catch::Contains("trailing slash"));
    CHECK_THROWS_AS(write_file_safely(name, bytes_of_text("x")), OutputError);
  }
  CHECK(names_in(folder).empty());
}

TEST_CASE("A replaced file keeps its owner, group and permission bits but never setuid or setgid",
          "[common][output_files][permissions]") {
  const testing::ScratchFolder scratch("owner");
  const fs::path& folder = scratch.path();
  write_text(folder / "tool", "old");
  ::chmod((folder / "tool").c_str(), 06750);
  write_file_safely(folder / "tool", bytes_of_text("new"));
  CHECK((status_of(folder / "tool").st_mode & 07777) == 0750);

  write_text(folder / "theirs", "old");
  uid_t owner = ::geteuid();
  gid_t group = ::getegid();
  if (running_as_root()) {
    owner = 4321;  // any ids will do: root may give a file to anyone
    group = 4322;
  } else {
    std::vector<gid_t> groups(static_cast<std::size_t>(::getgroups(0, nullptr)));
    ::getgroups(static_cast<int>(groups.size()), groups.data());
    const auto other =
        std::find_if(groups.begin(), groups.end(), [](gid_t g) { return g != ::getegid(); });
    if (other == groups.end()) {
      WARN("skipped: not root and in one group only, so no file here can belong to another");
      return;
    }
    group = *other;
  }
  REQUIRE(::chown((folder / "theirs").c_str(), owner, group) == 0);
  ::chmod((folder / "theirs").c_str(), 0640);
  write_file_safely(folder / "theirs", bytes_of_text("new"));
  const struct stat info = status_of(folder / "theirs");
  CHECK(read_text(folder / "theirs") == "new");
  CHECK(info.st_uid == owner);
  CHECK(info.st_gid == group);
  CHECK((info.st_mode & 07777) == 0640);
}

TEST_CASE(
    "A link in a sticky world-writable folder is followed only if its folder's owner or the "
    "user owns it",
    "[common][output_files][links]") {
  const testing::ScratchFolder scratch("sticky");
  const fs::path shared = scratch / "shared";
  fs::create_directory(shared);
  REQUIRE(::chmod(shared.c_str(), 01777) == 0);
  write_text(scratch / "victim", "precious");
  fs::create_symlink(scratch / "victim", shared / "mine.png");
  write_file_safely(shared / "mine.png", bytes_of_text("mine"));  // the user's own link
  CHECK(read_text(scratch / "victim") == "mine");
  CHECK(fs::is_symlink(shared / "mine.png"));
  if (!running_as_root()) {
    WARN("skipped the planted link: only root can make a link owned by another user");
    return;
  }
  write_text(scratch / "victim", "precious");
  fs::create_symlink(scratch / "victim", shared / "planted.png");
  REQUIRE(::lchown((shared / "planted.png").c_str(), 4321, 4321) == 0);
  const std::vector<fs::path> outputs{shared / "planted.png"};
  CHECK_THROWS_WITH(check_outputs(outputs), Catch::Contains("sticky world-writable"));
  CHECK_THROWS_WITH(write_file_safely(shared / "planted.png", bytes_of_text("x")),
                    Catch::Contains("sticky world-writable"));
  CHECK(read_text(scratch / "victim") == "precious");
  REQUIRE(::chown(shared.c_str(), 4321, 4321) == 0);  // now the folder's owner owns the link
  write_file_safely(shared / "planted.png", bytes_of_text("theirs"));
  CHECK(read_text(scratch / "victim") == "theirs");
}

TEST_CASE("Descriptor names write to the descriptor and never replace the file behind it",
          "[common][output_files][standard_output]") {
  const testing::ScratchFolder scratch("descriptors");
  write_text(scratch / "run.log", "earlier\n");
  const int log = ::open((scratch / "run.log").c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  REQUIRE(log >= 0);
  const ino_t inode = status_of(scratch / "run.log").st_ino;
  std::ostringstream standard_output;
  {
    OutputTransaction outputs(&standard_output);
    outputs.stage("/dev/fd/" + std::to_string(log), bytes_of_text("one "));
    outputs.stage("/dev/stdout", bytes_of_text("to standard output"));
    CHECK(read_text(scratch / "run.log") == "earlier\n");
    outputs.commit();
  }
  write_file_safely("/proc/self/fd/" + std::to_string(log), bytes_of_text("two"));
  ::close(log);
  CHECK(read_text(scratch / "run.log") == "earlier\none two");
  CHECK(status_of(scratch / "run.log").st_ino == inode);
  CHECK(standard_output.str() == "to standard output");
  CHECK(names_in(scratch.path()) == std::vector<std::string>{"run.log"});

  CHECK(output_descriptor("-") == 1);
  CHECK(output_descriptor("/dev/stderr") == 2);
  CHECK(output_descriptor(scratch / "run.log") == std::nullopt);
  const std::vector<fs::path> both_standard_output{"-", "/dev/stdout"};
  CHECK_THROWS_WITH(check_outputs(both_standard_output), Catch::Contains("name one file"));
  const std::vector<fs::path> closed{"/dev/fd/999"};
  CHECK_THROWS_WITH(check_outputs(closed), Catch::Contains("descriptor 999 is not open"));
  CHECK_THROWS_WITH(write_file_safely("/dev/stdout", bytes_of_text("x")),
                    Catch::Contains("cannot go to standard output"));
}

TEST_CASE("A failed write to standard output replaces no file",
          "[common][output_files][standard_output]") {
  const testing::ScratchFolder scratch("full_standard_output");
  write_text(scratch / "counts.pgm", "earlier counts");
  std::ofstream full("/dev/full");
  {
    OutputTransaction outputs(&full);
    outputs.stage("-", bytes_of_text("a picture"));
    outputs.stage(scratch / "counts.pgm", bytes_of_text("new counts"));
    CHECK_THROWS_WITH(outputs.commit(), Catch::Contains("No space left on device"));
  }
  CHECK(read_text(scratch / "counts.pgm") == "earlier counts");
  CHECK(names_in(scratch.path()) == std::vector<std::string>{"counts.pgm"});
}

}  // namespace tri
