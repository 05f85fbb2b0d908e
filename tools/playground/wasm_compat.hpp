/// @file
/// Force-included (-include) in the playground's WebAssembly build only, never in the native one.
/// Emscripten 3.1.6, Debian 12's, ships a libc++ older than the C++20 the chapters are written
/// in: it has no std::bit_cast and no std::jthread. This header supplies the two, as thin as the
/// standard describes them, so the chapters' sources compile unchanged. A newer libc++ has both
/// and the feature-test macros switch this header off.
#pragma once

#include <bit>
#include <thread>
#include <type_traits>
#include <utility>
#include <version>

#if !defined(__cpp_lib_bit_cast)
namespace std {
template <class To, class From>
requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> &&
         is_trivially_copyable_v<From>) constexpr To bit_cast(const From& from) noexcept {
  return __builtin_bit_cast(To, from);
}
}  // namespace std
#endif

#if !defined(__cpp_lib_jthread)
namespace std {
/// A std::thread that joins when it is destroyed (no stop token: the chapters use none).
class jthread {
 public:
  jthread() noexcept = default;
  template <class F, class... Args>
  requires(!is_same_v<remove_cvref_t<F>, jthread>) explicit jthread(F&& f, Args&&... args)
      : thread_(std::forward<F>(f), std::forward<Args>(args)...) {}
  jthread(jthread&&) noexcept = default;
  jthread& operator=(jthread&& other) noexcept {
    if (thread_.joinable()) thread_.join();
    thread_ = std::move(other.thread_);
    return *this;
  }
  ~jthread() {
    if (thread_.joinable()) thread_.join();
  }
  bool joinable() const noexcept { return thread_.joinable(); }
  void join() { thread_.join(); }

 private:
  thread thread_;
};
}  // namespace std
#endif
