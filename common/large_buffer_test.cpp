#include <cstdint>
#include <cstring>
#include <vector>

#include <catch2/catch.hpp>

#include "common/large_buffer.hpp"

TEST_CASE("A large buffer starts on a huge page and holds every byte written into it",
          "[common][large_buffer]") {
  const std::size_t bytes = tri::huge_page_bytes + 12345;  // the kernel backs aligned 2 MB only
  auto* buffer = static_cast<unsigned char*>(tri::allocate_large_buffer(bytes));
  REQUIRE(buffer != nullptr);
#if defined(__linux__)
  CHECK(reinterpret_cast<std::uintptr_t>(buffer) % tri::huge_page_bytes == 0);
#endif
  for (std::size_t i = 0; i < bytes; ++i) buffer[i] = static_cast<unsigned char>(i * 7);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < bytes; ++i)
    differing += buffer[i] != static_cast<unsigned char>(i * 7);
  CHECK(differing == 0);
  tri::release_large_buffer(buffer, bytes);
}

TEST_CASE("A vector over LargeBufferAllocator keeps its elements through growth, small and large",
          "[common][large_buffer]") {
  std::vector<std::uint64_t, tri::LargeBufferAllocator<std::uint64_t>> values;
  const std::size_t count = 3 * tri::huge_page_bytes / sizeof(std::uint64_t);
  for (std::size_t i = 0; i < count; ++i) values.push_back(i * i);  // grows through both kinds
  std::size_t differing = 0;
  for (std::size_t i = 0; i < count; ++i) differing += values[i] != i * i;
  CHECK(differing == 0);
  CHECK(values.size() == count);
  CHECK_THROWS_AS(values.reserve(values.max_size() + 1), std::length_error);
}
