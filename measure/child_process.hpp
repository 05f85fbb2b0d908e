/// @file
/// Running a piece of work in a forked child process and getting its result back, for work that
/// must not share this process's state: Mesa's llvmpipe reads its thread count once per process.
#pragma once

#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace tri {

/// Forks, runs work() in the child and returns the bytes it produced. The child ends with
/// _exit, so it never flushes this process's buffers or runs its exit handlers twice. Throws
/// std::runtime_error with the child's message if work() threw, or with how the child ended if
/// it died without an answer (a crash, a signal).
std::string run_in_child_process(const std::function<std::string()>& work);

/// run_in_child_process for a result that is plain bytes (no pointers to follow).
template <class Result>
requires std::is_trivially_copyable_v<Result> && std::is_default_constructible_v<Result> Result
run_in_child(const std::function<Result()>& work) {
  const std::string bytes = run_in_child_process([&work] {
    const Result result = work();
    return std::string(reinterpret_cast<const char*>(&result), sizeof result);
  });
  if (bytes.size() != sizeof(Result)) {
    throw std::runtime_error("a child process answered " + std::to_string(bytes.size()) +
                             " bytes where " + std::to_string(sizeof(Result)) + " were expected");
  }
  Result result;
  std::memcpy(&result, bytes.data(), sizeof result);
  return result;
}

}  // namespace tri
