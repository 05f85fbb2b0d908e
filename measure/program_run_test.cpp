#include "measure/program_run.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <stdexcept>
#include <string>

namespace tri {

TEST_CASE("run_program keeps what a program printed on each stream and how it ended",
          "[measure][program_run]") {
  const ProgramRun run = run_program({"/bin/sh", "-c", "printf out; printf err >&2; exit 3"});
  CHECK(run.output == "out");
  CHECK(run.errors == "err");
  CHECK(run.exit_code == 3);
  CHECK(run.signal == 0);
  CHECK_FALSE(run.timed_out);
  CHECK_FALSE(run.succeeded());

  const ProgramRun signalled = run_program({"/bin/sh", "-c", "kill -TERM $$"});
  CHECK(signalled.exit_code == -1);
  CHECK(signalled.signal == SIGTERM);
  CHECK_FALSE(signalled.timed_out);
}

TEST_CASE("A program past its deadline is killed and said to have run out of time",
          "[measure][program_run]") {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(50);
  const ProgramRun run = run_program({"/bin/sleep", "30"}, {.deadline = deadline});
  CHECK(run.timed_out);
  CHECK(run.signal == SIGKILL);
  CHECK(run.exit_code == -1);

  // A program that ends before its deadline is waited for, not killed.
  const ProgramRun quick =
      run_program({"/bin/sh", "-c", "printf done"},
                  {.deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60)});
  CHECK_FALSE(quick.timed_out);
  CHECK(quick.succeeded());
  CHECK(quick.output == "done");
}

TEST_CASE("A bare program name is looked up in PATH only when asked, and output can be discarded",
          "[measure][program_run]") {
  CHECK_THROWS_WITH(run_program({"sh", "-c", "exit 0"}), Catch::Contains("cannot start sh"));
  const ProgramRun searched = run_program(
      {"sh", "-c", "printf out"}, {.search_path = true, .discard_output = false, .deadline = {}});
  CHECK(searched.succeeded());
  CHECK(searched.output == "out");
  const ProgramRun discarded =
      run_program({"/bin/sh", "-c", "printf out; printf err >&2"},
                  {.search_path = false, .discard_output = true, .deadline = {}});
  CHECK(discarded.output.empty());
  CHECK(discarded.errors == "err");
  CHECK_THROWS_AS(run_program({}), std::invalid_argument);
}

}  // namespace tri
