/// @file
/// Memory for a large array filled once and read many times (a prepared batch of triangles): on
/// Linux a buffer of at least huge_page_bytes is mapped on huge-page boundaries and offered
/// transparent huge pages, so filling it costs a few page faults instead of one per 4 KB page.
#pragma once

#include <cstddef>
#include <limits>
#include <new>

namespace tri {

/// The size of a transparent huge page on x86-64 and arm64 Linux; smaller buffers come from new.
inline constexpr std::size_t huge_page_bytes = std::size_t{2} << 20;

/// Memory for `bytes` bytes, aligned for any type; throws std::bad_alloc when there is none.
void* allocate_large_buffer(std::size_t bytes);

/// Gives back what allocate_large_buffer(bytes) returned, with the same `bytes`.
void release_large_buffer(void* buffer, std::size_t bytes) noexcept;

/// A standard allocator over allocate_large_buffer, for a std::vector that holds many elements.
template <class T>
struct LargeBufferAllocator {
  using value_type = T;

  LargeBufferAllocator() = default;
  template <class U>
  explicit(false) LargeBufferAllocator(const LargeBufferAllocator<U>& /*other*/) noexcept {}

  T* allocate(std::size_t count) {
    if (count > std::numeric_limits<std::size_t>::max() / sizeof(T))
      throw std::bad_array_new_length();
    return static_cast<T*>(allocate_large_buffer(count * sizeof(T)));
  }
  void deallocate(T* buffer, std::size_t count) noexcept {
    release_large_buffer(buffer, count * sizeof(T));
  }
  template <class U>
  bool operator==(const LargeBufferAllocator<U>& /*other*/) const noexcept {
    return true;
  }
};

}  // namespace tri
