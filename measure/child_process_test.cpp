#include "measure/child_process.hpp"

#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <cstdlib>
#include <string>

namespace {

struct Answer {
  int pid = 0;
  double value = 0;
};

}  // namespace

TEST_CASE("A child process returns its result to the parent", "[measure][child_process]") {
  const Answer answer = tri::run_in_child<Answer>([] { return Answer{::getpid(), 2.5}; });
  CHECK(answer.value == 2.5);
  CHECK(answer.pid != ::getpid());  // it really ran elsewhere
}

TEST_CASE("What a child changes stays in the child", "[measure][child_process]") {
  ::unsetenv("TRI_CHILD_PROCESS_TEST");
  const int seen = tri::run_in_child<int>([] {
    ::setenv("TRI_CHILD_PROCESS_TEST", "1", 1);
    return std::getenv("TRI_CHILD_PROCESS_TEST") != nullptr ? 1 : 0;
  });
  CHECK(seen == 1);
  CHECK(std::getenv("TRI_CHILD_PROCESS_TEST") == nullptr);
}

TEST_CASE("A child's exception reaches the parent with its message", "[measure][child_process]") {
  CHECK_THROWS_WITH(tri::run_in_child<int>(
                        []() -> int { throw std::runtime_error("no GL context in the child"); }),
                    "no GL context in the child");
}

TEST_CASE("A child that dies without answering is reported, not trusted",
          "[measure][child_process]") {
  CHECK_THROWS_WITH(tri::run_in_child<int>([]() -> int { ::_exit(3); }),
                    "a child process exited with status 3 without an answer");
  CHECK_THROWS_WITH(tri::run_in_child<int>([]() -> int {
                      std::raise(SIGKILL);
                      return 0;
                    }),
                    "a child process was killed by signal 9 without an answer");
}
