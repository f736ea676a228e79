// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// enum_name(): the to_string() of the aico enums, written once (internal).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>

namespace topograsp::detail {

/// The name of \p e, an enumerator of an enum whose enumerators are 0..N-1 in declaration order,
/// from \p names (one per enumerator, in that order); "unknown" for any other value.
template <class E, std::size_t N>
  requires std::is_enum_v<E>
[[nodiscard]] constexpr std::string_view enum_name(
    E e, const std::array<std::string_view, N>& names) noexcept {
  const auto i = static_cast<std::size_t>(e);
  return i < N ? names[i] : std::string_view("unknown");
}

}  // namespace topograsp::detail
