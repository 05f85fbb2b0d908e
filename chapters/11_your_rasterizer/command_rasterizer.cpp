#include "chapters/11_your_rasterizer/command_rasterizer.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>

#include "common/cli.hpp"
#include "common/image_io.hpp"
#include "common/printable_text.hpp"
#include "measure/scene_text.hpp"

extern char** environ;

namespace tri::conformance {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// A private folder for the scene and counts files of one graded program, removed at the end.
class WorkFolder {
 public:
  WorkFolder() {
    std::string pattern = (fs::temp_directory_path() / "conformance_XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      throw std::runtime_error("cannot make a temporary folder: " +
                               std::string(std::strerror(errno)));
    }
    path_ = pattern;
  }
  WorkFolder(const WorkFolder&) = delete;
  WorkFolder& operator=(const WorkFolder&) = delete;
  ~WorkFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }
  /// A new number for each run's files, so that nothing a killed run left behind is read again.
  int next_run() noexcept { return ++runs_; }

 private:
  fs::path path_;
  int runs_ = 0;
};

std::string replaced(std::string word, std::string_view placeholder, const std::string& value) {
  for (auto at = word.find(placeholder); at != std::string::npos;
       at = word.find(placeholder, at + value.size())) {
    word.replace(at, placeholder.size(), value);
  }
  return word;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string signal_name(int signal) {
  const char* description = strsignal(signal);
  return "signal " + std::to_string(signal) +
         (description ? " (" + std::string(description) + ")" : "");
}

Answer failed(std::string reason) {
  return {.kind = Answer::Kind::failed, .counts = {}, .reason = std::move(reason)};
}

// Starts the program; returns its process id or throws with the system's reason.
pid_t spawn(const std::vector<std::string>& words, const fs::path& error_file) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, error_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  // In this process's group, so that an interrupt from the terminal (Ctrl-C) ends it too.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  std::vector<char*> argv;
  for (const auto& word : words) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) {
    throw std::runtime_error("cannot start " + printable_text(words[0]) + ": " +
                             std::strerror(error));
  }
  return pid;
}

// Waits for the program until the deadline; kills it past it. The wait status,
// or nothing when it was killed for the time.
std::optional<int> wait_until(pid_t pid, Deadline deadline) {
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    int status = 0;
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) return status;
    if (done < 0 && errno != EINTR) return std::nullopt;
    if (Clock::now() > deadline) {
      kill(pid, SIGKILL);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      return std::nullopt;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(5'000));
  }
}

Answer run_once(const std::vector<std::string>& words, WorkFolder& folder, const Scene& scene,
                Deadline deadline) {
  const std::string run = std::to_string(folder.next_run());
  const fs::path scene_file = folder.path() / ("scene_" + run + ".txt");
  const fs::path counts_file = folder.path() / ("counts_" + run + ".pgm");
  const fs::path error_file = folder.path() / ("stderr_" + run + ".txt");
  {
    std::ofstream out(scene_file, std::ios::binary | std::ios::trunc);
    out << scene_text(scene);
    if (!out.flush())
      throw std::runtime_error("cannot write the scene file " + scene_file.string());
  }
  std::vector<std::string> argv;
  for (const auto& word : words) {
    argv.push_back(
        replaced(replaced(word, "{scene}", scene_file.string()), "{counts}", counts_file.string()));
  }
  pid_t pid = 0;
  try {
    pid = spawn(argv, error_file);
  } catch (const std::runtime_error& e) {
    return failed(e.what());
  }
  const std::optional<int> status = wait_until(pid, deadline);
  // The program's own words, whole up to a line's worth (a refusal says why), escaped.
  std::string said = read_file(error_file);
  while (!said.empty() && (said.back() == '\n' || said.back() == '\r')) said.pop_back();
  const std::string message =
      said.size() <= 400 ? printable_text(said) : printable_text(said.substr(0, 400)) + "...";
  if (!status) return failed("did not finish in time and was killed");
  if (WIFSIGNALED(*status)) {
    return failed("crashed: " + signal_name(WTERMSIG(*status)) +
                  (message.empty() ? "" : ", saying " + message));
  }
  const int code = WIFEXITED(*status) ? WEXITSTATUS(*status) : -1;
  if (code != 0) {
    if (message.empty())
      return failed("exit status " + std::to_string(code) + " without a message");
    return {.kind = Answer::Kind::refused,
            .counts = {},
            .reason = "exit status " + std::to_string(code) + ": " + message};
  }
  const std::string bytes = read_file(counts_file);
  if (bytes.empty()) return failed("exit status 0, but no counts file was written");
  try {
    CountsImage image =
        decode_counts_pgm({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
    if (image.width != scene.width || image.height != scene.height) {
      return failed("counts of " + std::to_string(image.width) + "x" +
                    std::to_string(image.height) + " pixels for a " + std::to_string(scene.width) +
                    "x" + std::to_string(scene.height) + " canvas");
    }
    return {.kind = Answer::Kind::counts, .counts = std::move(image.counts), .reason = {}};
  } catch (const std::runtime_error& e) {
    return failed(std::string("unreadable counts: ") + e.what());
  }
}

}  // namespace

std::vector<std::string> command_words(std::string_view command) {
  std::vector<std::string> words;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (const char c : command) {
    if (quote != 0) {
      if (c == quote) {
        quote = 0;
      } else {
        word += c;
      }
    } else if (c == '\'' || c == '"') {
      quote = c;
      in_word = true;
    } else if (c == ' ' || c == '\t') {
      if (in_word) words.push_back(std::move(word));
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (quote != 0) throw UsageError("--command has an unclosed quote");
  if (in_word) words.push_back(std::move(word));
  if (words.empty()) throw UsageError("--command is empty");
  const auto names = [&words](std::string_view placeholder) {
    return std::any_of(words.begin(), words.end(), [&](const std::string& w) {
      return w.find(placeholder) != std::string::npos;
    });
  };
  if (!names("{scene}") || !names("{counts}")) {
    throw UsageError(
        "--command must name both {scene} and {counts}, the files it reads and writes");
  }
  return words;
}

GradedRasterizer graded_command(std::string_view command) {
  auto words = command_words(command);
  auto folder = std::make_shared<WorkFolder>();
  return {
      .name = std::string(command),
      .threaded = false,
      .draw = [words = std::move(words), folder](const Scene& scene, Threads, Deadline deadline) {
        return run_once(words, *folder, scene, deadline);
      }};
}

}  // namespace tri::conformance
