// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Name: a short fixed-capacity string that can live in a constexpr model.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

namespace topograsp {

namespace detail {
/// Not constexpr on purpose: reaching it while a model is built at compile time is a compile
/// error, and the compiler shows the call with its message (for example "duplicate name").
inline void model_error(const char* /*why*/) {}
}  // namespace detail

/// The longest name a model accepts (characters, without the terminating zero).
inline constexpr std::size_t max_name_length = 31;

/// A fixed-capacity string of at most 31 characters, a structural literal type.
struct Name {
  std::array<char, max_name_length + 1> chars{};

  constexpr Name() = default;
  // NOLINTNEXTLINE(google-explicit-constructor): names are written as string literals.
  constexpr Name(std::string_view s) {
    if (s.size() > max_name_length) detail::model_error("name longer than 31 characters");
    for (std::size_t i = 0; i < s.size() && i < max_name_length; ++i) chars[i] = s[i];
  }
  // NOLINTNEXTLINE(google-explicit-constructor)
  constexpr Name(const char* s) : Name(std::string_view(s)) {}

  [[nodiscard]] constexpr std::size_t size() const noexcept {
    std::size_t n = 0;
    while (n < max_name_length && chars[n] != '\0') ++n;
    return n;
  }
  [[nodiscard]] constexpr bool empty() const noexcept { return chars[0] == '\0'; }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {chars.data(), size()}; }
  friend constexpr bool operator==(const Name&, const Name&) = default;
};

}  // namespace topograsp
