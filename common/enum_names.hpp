/// @file
/// An enumeration's values and their names in one table, so that naming a value and reading a
/// name back are the same lookup for every enumeration that has names.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace tri {

/// The names of N values of Enum, one entry per value.
template <class Enum, std::size_t N>
using EnumNames = std::array<std::pair<Enum, std::string_view>, N>;

/// The names of every value of an enumeration whose values are 0, 1, ..., `last`, checked when
/// compiled: the entries must name them in order, so that a value added to the enumeration but
/// not to its names stops the build, as a switch's -Wswitch would.
template <auto last, std::size_t N>
consteval EnumNames<decltype(last), N> all_names(
    const std::pair<decltype(last), std::string_view> (&names)[N]) {
  if (static_cast<std::size_t>(last) + 1 != N) throw "a value of the enumeration has no name";
  EnumNames<decltype(last), N> table{};
  for (std::size_t i = 0; i < N; ++i) {
    if (static_cast<std::size_t>(names[i].first) != i) throw "the names are not in value order";
    table[i] = names[i];
  }
  return table;
}

/// The name of `value`, or `fallback` for a value the table does not hold.
template <class Enum, std::size_t N>
constexpr std::string_view name_in(const EnumNames<Enum, N>& names, Enum value,
                                   std::string_view fallback) noexcept {
  for (const auto& [v, name] : names) {
    if (v == value) return name;
  }
  return fallback;
}

/// The value named `name`, or nothing for another word.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> value_named(const EnumNames<Enum, N>& names,
                                          std::string_view name) noexcept {
  for (const auto& [v, n] : names) {
    if (n == name) return v;
  }
  return std::nullopt;
}

}  // namespace tri
