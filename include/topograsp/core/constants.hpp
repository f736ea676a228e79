// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Constants (SI units everywhere: metres, kilograms, seconds, radians).
#pragma once

#include <numbers>

namespace topograsp {

inline constexpr double pi = std::numbers::pi;
inline constexpr double two_pi = 2.0 * std::numbers::pi;
/// Standard gravity in m/s^2.
inline constexpr double standard_gravity = 9.80665;

/// Degrees to radians.
[[nodiscard]] constexpr double deg(double degrees) noexcept { return degrees * pi / 180.0; }

}  // namespace topograsp
