// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// constexpr sin, cos and sqrt for building models at compile time (std:: versions are not
/// constexpr in C++20). Accurate to a few ulp on the ranges models use; not for hot loops.
#pragma once

#include <topograsp/core/constants.hpp>

namespace topograsp::cmath {

[[nodiscard]] constexpr double abs(double x) noexcept { return x < 0.0 ? -x : x; }

namespace detail {
// Reduces x to [-pi, pi].
constexpr double reduce(double x) noexcept {
  if (x > pi || x < -pi) {
    const double k = static_cast<double>(static_cast<long long>(x / two_pi));
    x -= k * two_pi;
    if (x > pi) x -= two_pi;
    if (x < -pi) x += two_pi;
  }
  return x;
}
// Taylor series on [-pi/4, pi/4].
constexpr double sin_small(double x) noexcept {
  const double x2 = x * x;
  double term = x, sum = x;
  for (int n = 1; n < 12; ++n) {
    term *= -x2 / static_cast<double>((2 * n) * (2 * n + 1));
    sum += term;
  }
  return sum;
}
constexpr double cos_small(double x) noexcept {
  const double x2 = x * x;
  double term = 1.0, sum = 1.0;
  for (int n = 1; n < 12; ++n) {
    term *= -x2 / static_cast<double>((2 * n - 1) * (2 * n));
    sum += term;
  }
  return sum;
}
}  // namespace detail

/// sin(x), usable in constant expressions.
[[nodiscard]] constexpr double sin(double x) noexcept {
  x = detail::reduce(x);
  // sin(x) from the octant: x = k * pi/2 + r with |r| <= pi/4.
  const double half_pi = pi / 2.0;
  const double kf = x >= 0.0 ? static_cast<double>(static_cast<long long>(x / half_pi + 0.5))
                             : -static_cast<double>(static_cast<long long>(-x / half_pi + 0.5));
  const double r = x - kf * half_pi;
  switch ((static_cast<long long>(kf) % 4 + 4) % 4) {
    case 0:
      return detail::sin_small(r);
    case 1:
      return detail::cos_small(r);
    case 2:
      return -detail::sin_small(r);
    default:
      return -detail::cos_small(r);
  }
}

/// cos(x), usable in constant expressions.
[[nodiscard]] constexpr double cos(double x) noexcept { return sin(x + pi / 2.0); }

/// sqrt(x) for x >= 0 by Newton's method, usable in constant expressions; 0 for x <= 0.
[[nodiscard]] constexpr double sqrt(double x) noexcept {
  if (!(x > 0.0)) return 0.0;
  double r = x > 1.0 ? x : 1.0;
  for (int i = 0; i < 200; ++i) {
    const double next = 0.5 * (r + x / r);
    if (next == r) break;
    r = next;
  }
  return r;
}

}  // namespace topograsp::cmath
