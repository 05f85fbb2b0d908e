#include "common/large_buffer.hpp"

#if defined(__linux__)
#include <sys/mman.h>

#include <cstdint>
#endif

namespace tri {
#if defined(__linux__)
namespace {

std::size_t whole_huge_pages(std::size_t bytes) noexcept {
  return (bytes + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
}

}  // namespace
#endif

void* allocate_large_buffer(std::size_t bytes) {
#if defined(__linux__)
  if (bytes >= huge_page_bytes) {
    // Mapped one huge page larger, then trimmed to the huge pages inside: the kernel backs only
    // aligned 2 MB ranges with huge pages.
    const std::size_t kept = whole_huge_pages(bytes), mapped = kept + huge_page_bytes;
    void* raw = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned =
        (start + huge_page_bytes - 1) / huge_page_bytes * huge_page_bytes;
    const std::size_t head = aligned - start, tail = mapped - head - kept;
    if (head > 0) munmap(raw, head);
    if (tail > 0) munmap(reinterpret_cast<void*>(aligned + kept), tail);
    madvise(reinterpret_cast<void*>(aligned), kept, MADV_HUGEPAGE);  // advice only: may be off
    return reinterpret_cast<void*>(aligned);
  }
#endif
  return ::operator new(bytes);
}

void release_large_buffer(void* buffer, [[maybe_unused]] std::size_t bytes) noexcept {
  if (buffer == nullptr) return;
#if defined(__linux__)
  if (bytes >= huge_page_bytes) {
    munmap(buffer, whole_huge_pages(bytes));
    return;
  }
#endif
  ::operator delete(buffer);
}

}  // namespace tri
