#include "measure/child_process.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <iostream>

namespace tri {
namespace {

// The child's answer starts with one of these, so a message is never read as a result.
constexpr char answer_result = 'R';
constexpr char answer_error = 'E';

void write_all(int fd, const std::string& bytes) noexcept {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent will see a short answer and say so
    written += static_cast<std::size_t>(n);
  }
}

std::string read_all(int fd) {
  std::string bytes;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return bytes;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
}

std::string how_it_ended(int status) {
  if (WIFSIGNALED(status)) return "was killed by signal " + std::to_string(WTERMSIG(status));
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  return "ended with wait status " + std::to_string(status);
}

}  // namespace

std::string run_in_child_process(const std::function<std::string()>& work) {
  int channel[2];
  if (::pipe(channel) != 0) throw std::runtime_error("could not create a pipe for a child process");
  // Whatever is buffered now would otherwise be written twice, once by each process.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(channel[0]);
    ::close(channel[1]);
    throw std::runtime_error("could not fork a child process");
  }
  if (child == 0) {
    ::close(channel[0]);
    std::string answer;
    try {
      answer = answer_result + work();
    } catch (const std::exception& error) {
      answer = answer_error + std::string(error.what());
    } catch (...) {
      answer = answer_error + std::string("an exception that is not a std::exception");
    }
    write_all(channel[1], answer);
    ::close(channel[1]);
    ::_exit(0);
  }
  ::close(channel[1]);
  const std::string answer = read_all(channel[0]);
  ::close(channel[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (answer.empty()) {
    throw std::runtime_error("a child process " + how_it_ended(status) + " without an answer");
  }
  if (answer.front() == answer_error) throw std::runtime_error(answer.substr(1));
  if (answer.front() != answer_result) {
    throw std::runtime_error("a child process answered something unreadable");
  }
  return answer.substr(1);
}

}  // namespace tri
