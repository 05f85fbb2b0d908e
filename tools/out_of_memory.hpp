/// @file
/// Running out of memory in raster says what was being allocated, how much, and what to lower,
/// instead of `std::bad_alloc` (docs/DESIGN.md section 9).
#pragma once

#include <cstdint>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>

namespace tri {

/// "512 KiB", "1.0 GiB": a size in bytes as a person reads it.
std::string human_bytes(double bytes);

/// Calls allocate() and returns its result; when it runs out of memory, throws
/// std::runtime_error "out of memory while allocating WHAT (SIZE); lower LOWER".
template <class Allocate>
auto allocating(const std::string& what, double bytes, const std::string& lower,
                Allocate&& allocate) -> decltype(std::forward<Allocate>(allocate)()) {
  try {
    return std::forward<Allocate>(allocate)();
  } catch (const std::bad_alloc&) {
    throw std::runtime_error("out of memory while allocating " + what + " (" + human_bytes(bytes) +
                             "); lower " + lower);
  }
}

}  // namespace tri
