// The raster executable run as a user runs it, for what only a separate process shows: its
// standard streams as descriptors, signals, and a lock held by another process.
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "tests/support/scratch_folder.hpp"
#include "tools/raster_app.hpp"

namespace {

namespace fs = std::filesystem;
using tri::testing::has_unnamed_temporaries;
using tri::testing::names_in;
using tri::testing::read_text;
using tri::testing::ScratchFolder;
using tri::testing::write_text;

constexpr const char* scene_text = "canvas 8 8\nline 0 0 7 7\ntri 1 1 6 1 1 6\n";

// A scratch folder holding the test scene as s.scene and the earlier files given as (name, text).
struct SceneFolder : ScratchFolder {
  explicit SceneFolder(const std::string& name,
                       const std::vector<std::pair<std::string, std::string>>& earlier = {})
      : ScratchFolder(name) {
    write_text(*this / "s.scene", scene_text);
    for (const auto& [file, text] : earlier) write_text(*this / file, text);
  }
};

// What raster writes for the scene, run in this process: the PNG and the write counts.
struct Expected {
  std::string png;
  std::string pgm;
};

Expected expected_outputs() {
  const SceneFolder scratch("expected");
  const std::string scene = (scratch / "s.scene").string();
  const std::string png = (scratch / "a.png").string();
  const std::string pgm = (scratch / "c.pgm").string();
  const char* argv[] = {"raster", "--algo",    "edge_function", "--scene",  scene.c_str(),
                        "--out",  png.c_str(), "--counts",      pgm.c_str()};
  std::ostringstream out, err;
  REQUIRE(tri::run_raster(9, argv, out, err) == 0);
  return {read_text(png), read_text(pgm)};
}

// Arguments that draw the scratch folder's s.scene with edge_function, then the output options.
std::vector<std::string> drawing_the_scene(const SceneFolder& scratch,
                                           const std::vector<std::string>& outputs) {
  std::vector<std::string> args{"--algo", "edge_function", "--scene",
                                (scratch / "s.scene").string()};
  args.insert(args.end(), outputs.begin(), outputs.end());
  return args;
}

// Where the child's standard streams go; -1 leaves one as it is in the test.
struct Streams {
  int output = -1;
  int error = -1;
};

// Starts the raster executable with args; stop_after_outputs asks it to stop itself after each
// staged output (the test hook of common/output_files.cpp).
pid_t start_raster(const std::vector<std::string>& args, Streams streams,
                   bool stop_after_outputs = false) {
  std::vector<std::string> words{RASTER_EXECUTABLE};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    if (streams.output >= 0) ::dup2(streams.output, STDOUT_FILENO);
    if (streams.error >= 0) ::dup2(streams.error, STDERR_FILENO);
    ::signal(SIGPIPE, SIG_DFL);
    if (stop_after_outputs) ::setenv("TUTORIAL_TEST_STOP_AFTER_EACH_OUTPUT", "1", 1);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return child;
}

int wait_for(pid_t child, int options = 0) {
  int status = 0;
  REQUIRE(::waitpid(child, &status, options) == child);
  return status;
}

// A descriptor, closed with the object and in a started program (only dup2 passes one on).
class OpenFile {
 public:
  OpenFile(const fs::path& path, int flags)
      : descriptor_(::open(path.c_str(), flags | O_CLOEXEC, 0666)) {
    REQUIRE(descriptor_ >= 0);
  }
  OpenFile(const OpenFile&) = delete;
  OpenFile& operator=(const OpenFile&) = delete;
  ~OpenFile() { ::close(descriptor_); }
  int get() const { return descriptor_; }

 private:
  int descriptor_;
};

// Whether /proc/locks shows process pid waiting for a lock (a line "N: -> FLOCK ... pid ...").
bool waits_for_a_lock(pid_t pid) {
  std::ifstream locks("/proc/locks");
  std::string line;
  while (std::getline(locks, line)) {
    if (line.find("->") == std::string::npos) continue;
    std::istringstream words(line);
    std::string word;
    while (words >> word) {
      if (word == std::to_string(pid)) return true;
    }
  }
  return false;
}

}  // namespace

TEST_CASE(
    "The raster executable replaces no file when standard output cannot be written, and says so "
    "once",
    "[raster][process]") {
  const SceneFolder scratch("full", {{"c.pgm", "earlier counts"}});
  const OpenFile full("/dev/full", O_WRONLY);
  const OpenFile log(scratch / "log", O_WRONLY | O_CREAT);
  const pid_t child = start_raster(
      drawing_the_scene(scratch, {"--out", "-", "--counts", (scratch / "c.pgm").string()}),
      {full.get(), log.get()});
  const int status = wait_for(child);
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 1);
  CHECK(read_text(scratch / "c.pgm") == "earlier counts");
  CHECK(read_text(scratch / "log") ==
        "raster: error: cannot write the results to standard output: No space left on device\n");
  CHECK(names_in(scratch.path()) == std::vector<std::string>{"c.pgm", "log", "s.scene"});
}

TEST_CASE("The raster executable replaces no file when standard output is a closed pipe",
          "[raster][process]") {
  const SceneFolder scratch("closed_pipe", {{"c.pgm", "earlier counts"}});
  int pipe_ends[2];
  REQUIRE(::pipe2(pipe_ends, O_CLOEXEC) == 0);
  ::close(pipe_ends[0]);  // nobody reads: the first write raises SIGPIPE
  const pid_t child = start_raster(
      drawing_the_scene(scratch, {"--out", "-", "--counts", (scratch / "c.pgm").string()}),
      {pipe_ends[1], -1});
  ::close(pipe_ends[1]);
  const int status = wait_for(child);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGPIPE);
  CHECK(read_text(scratch / "c.pgm") == "earlier counts");
  CHECK(names_in(scratch.path()) == std::vector<std::string>{"c.pgm", "s.scene"});
}

TEST_CASE(
    "The raster executable with --out /dev/stderr appends the PNG to the log standard error goes "
    "to",
    "[raster][process]") {
  const SceneFolder scratch("stderr_log", {{"run.log", "earlier log line\n"}});
  struct stat before {};
  REQUIRE(::stat((scratch / "run.log").c_str(), &before) == 0);
  const OpenFile log(scratch / "run.log", O_WRONLY | O_APPEND);
  const OpenFile summary(scratch / "summary", O_WRONLY | O_CREAT);
  const pid_t child = start_raster(drawing_the_scene(scratch, {"--out", "/dev/stderr"}),
                                   {summary.get(), log.get()});
  REQUIRE(wait_for(child) == 0);
  const std::string png = expected_outputs().png;
  CHECK(read_text(scratch / "run.log") == "earlier log line\n" + png);
  struct stat after {};
  REQUIRE(::stat((scratch / "run.log").c_str(), &after) == 0);
  CHECK(after.st_ino == before.st_ino);
  CHECK(read_text(scratch / "summary") ==
        "drew 1 triangle(s) and 1 line(s) on 8x8 with edge_function\n");

  // /dev/stdout into a pipe is standard output, as '-' is.
  int pipe_ends[2];
  REQUIRE(::pipe2(pipe_ends, O_CLOEXEC) == 0);
  const pid_t piped = start_raster(drawing_the_scene(scratch, {"--out", "/dev/stdout"}),
                                   {pipe_ends[1], summary.get()});
  ::close(pipe_ends[1]);
  std::string received;
  char buffer[4096];
  for (ssize_t got; (got = ::read(pipe_ends[0], buffer, sizeof buffer)) > 0;) {
    received.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(pipe_ends[0]);
  CHECK(wait_for(piped) == 0);
  CHECK(received == png);
}

TEST_CASE(
    "The raster executable interrupted between its two outputs leaves no temporary and the "
    "earlier files",
    "[raster][process][interrupts]") {
  for (const int stops : {1, 2}) {
    for (const int signal_number : {SIGINT, SIGTERM, SIGKILL}) {
      CAPTURE(stops, signal_number);
      const SceneFolder scratch("interrupted",
                                {{"a.png", "earlier picture"}, {"c.pgm", "earlier counts"}});
      const OpenFile quiet("/dev/null", O_WRONLY);
      const pid_t child =
          start_raster(drawing_the_scene(scratch, {"--out", (scratch / "a.png").string(),
                                                   "--counts", (scratch / "c.pgm").string()}),
                       {quiet.get(), quiet.get()}, true);
      for (int stop = 1; stop <= stops; ++stop) {
        const int status = wait_for(child, WUNTRACED);
        REQUIRE(WIFSTOPPED(status));
        if (stop < stops) ::kill(child, SIGCONT);
      }
      ::kill(child, signal_number);
      ::kill(child, SIGCONT);
      const int status = wait_for(child);
      CHECK(WIFSIGNALED(status));
      CHECK(WTERMSIG(status) == signal_number);
      CHECK(read_text(scratch / "a.png") == "earlier picture");
      CHECK(read_text(scratch / "c.pgm") == "earlier counts");
      const auto names = names_in(scratch.path());
      if (signal_number == SIGKILL && !has_unnamed_temporaries(scratch.path())) {
        WARN("no O_TMPFILE in " << scratch.path() << ": SIGKILL may leave named temporaries");
        CHECK(names.size() <= 3 + static_cast<std::size_t>(stops));
      } else {
        CHECK(names == std::vector<std::string>{"a.png", "c.pgm", "s.scene"});
      }
    }
  }
}

TEST_CASE(
    "The raster executable interrupted after its first output removes the folder it made for its "
    "outputs",
    "[raster][process][interrupts]") {
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
    const SceneFolder scratch("interrupted_folder");
    const OpenFile quiet("/dev/null", O_WRONLY);
    const pid_t child = start_raster(
        drawing_the_scene(scratch, {"--out", (scratch / "made" / "deeper" / "a.png").string(),
                                    "--counts", (scratch / "made" / "c.pgm").string()}),
        {quiet.get(), quiet.get()}, true);
    REQUIRE(WIFSTOPPED(wait_for(child, WUNTRACED)));
    CHECK(fs::is_directory(scratch / "made" / "deeper"));
    ::kill(child, signal_number);
    ::kill(child, SIGCONT);
    const int status = wait_for(child);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == signal_number);
    CHECK(names_in(scratch.path()) == std::vector<std::string>{"s.scene"});
  }
}

TEST_CASE(
    "The raster executable waits for a lock on its outputs' folder and then writes its pair "
    "together",
    "[raster][process][lock]") {
  const Expected expected = expected_outputs();
  const SceneFolder scratch("locked", {{"a.png", "earlier picture"}, {"c.pgm", "earlier counts"}});
  std::optional<OpenFile> lock;
  lock.emplace(scratch.path(), O_RDONLY | O_DIRECTORY);
  REQUIRE(::flock(lock->get(), LOCK_EX) == 0);  // as a parallel run holds it while it commits
  const OpenFile quiet("/dev/null", O_WRONLY);
  const pid_t child =
      start_raster(drawing_the_scene(scratch, {"--out", (scratch / "a.png").string(), "--counts",
                                               (scratch / "c.pgm").string()}),
                   {quiet.get(), quiet.get()});
  // Wait (as long as a loaded machine needs) until the kernel lists raster as a lock's waiter.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(2);
  while (!waits_for_a_lock(child) && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  REQUIRE(waits_for_a_lock(child));
  CHECK(::waitpid(child, nullptr, WNOHANG) == 0);
  CHECK(read_text(scratch / "a.png") == "earlier picture");
  CHECK(read_text(scratch / "c.pgm") == "earlier counts");
  lock.reset();
  CHECK(wait_for(child) == 0);
  CHECK(read_text(scratch / "a.png") == expected.png);
  CHECK(read_text(scratch / "c.pgm") == expected.pgm);
  CHECK(names_in(scratch.path()) == std::vector<std::string>{"a.png", "c.pgm", "s.scene"});
}
