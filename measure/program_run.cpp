#include "measure/program_run.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "common/printable_text.hpp"

extern char** environ;

namespace tri {
namespace {

// The wait status of the program; past the deadline it is killed first (timed_out is set).
int wait_for(pid_t pid, const ProgramOptions& options, const std::string& program,
             bool& timed_out) {
  int status = 0;
  const auto wait_or_throw = [&](int flags) {
    pid_t done = 0;
    while ((done = waitpid(pid, &status, flags)) < 0) {
      if (errno != EINTR) throw std::runtime_error("cannot wait for " + printable_text(program));
    }
    return done == pid;
  };
  if (!options.deadline) {
    wait_or_throw(0);
    return status;
  }
  // Polled, from 0.2 ms up to 5 ms between looks: a quick program is not held up by the pause.
  auto pause = std::chrono::microseconds(200);
  while (!wait_or_throw(WNOHANG)) {
    if (std::chrono::steady_clock::now() > *options.deadline) {
      kill(pid, SIGKILL);
      timed_out = true;
      wait_or_throw(0);
      return status;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(5'000));
  }
  return status;
}

}  // namespace

ProgramRun run_program(const std::vector<std::string>& words, const ProgramOptions& options) {
  if (words.empty()) throw std::invalid_argument("run_program needs a program to run");
  // Output goes to files, not pipes: a program that prints much to both cannot block on either.
  const TemporaryFolder folder("tri_program_run");
  const auto output_file = folder / "output", errors_file = folder / "errors";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  if (options.discard_output) {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  } else {
    posix_spawn_file_actions_addopen(&actions, 1, output_file.c_str(), O_WRONLY | O_CREAT, 0600);
  }
  posix_spawn_file_actions_addopen(&actions, 2, errors_file.c_str(), O_WRONLY | O_CREAT, 0600);
  std::vector<char*> argv;
  for (const auto& word : words) argv.push_back(const_cast<char*>(word.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = options.search_path
                        ? posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ)
                        : posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) {
    throw std::runtime_error("cannot start " + printable_text(words[0]) + ": " +
                             std::strerror(error));
  }
  ProgramRun run;
  const int status = wait_for(pid, options, words[0], run.timed_out);
  run.output = whole_file(output_file);
  run.errors = whole_file(errors_file);
  if (WIFEXITED(status)) run.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
  return run;
}

}  // namespace tri
