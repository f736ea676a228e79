// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// winding(): the paper's winding quantity of a piecewise-linear curve around a point, and its
/// exact gradient with respect to every vertex.
#pragma once

#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <ranges>
#include <span>
#include <string>
#include <string_view>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>

namespace topograsp {

/// A contiguous range of Eigen::Vector3d: std::vector, std::array, std::span, a C array.
template <class R>
concept PointRange =
    std::ranges::contiguous_range<R> && std::ranges::sized_range<R> &&
    std::same_as<std::remove_cvref_t<std::ranges::range_value_t<R>>, Eigen::Vector3d>;

namespace detail {

/// The exponent applied to bring vectors into the working range of angle_between() and
/// angle_gradient(): a vector whose largest component magnitude m lies in
/// [2^-k_winding_exponent, 2^k_winding_exponent] is used as it is (so the ordinary case is exactly
/// the plain formula); any other is scaled by the power of two 2^-e that brings m into [0.5, 1).
/// Within the range |a x b|^2 (fourth powers of the coordinates; Eigen's norm() squares) and
/// every product of angle_gradient() stay normal and finite.
inline constexpr int k_winding_exponent = 250;

/// Scales \p v by an exact power of two into the working range (see k_winding_exponent) and
/// writes the exponent e with v_before = v_after * 2^e into \p e (0 if it was not scaled).
/// Returns false (leaving \p v) if v's largest component is below the smallest normal double
/// (2.2e-308): such a vector counts as zero, as a vertex at the reference point does.
[[nodiscard]] inline bool to_working_range(Vec3& v, int& e) noexcept {
  const double m = v.cwiseAbs().maxCoeff();
  e = 0;
  if (!(m >= std::numeric_limits<double>::min())) return false;
  if (m >= 0x1p-250 && m <= 0x1p250) return true;  // 2^-+k_winding_exponent
  (void)std::frexp(m, &e);
  v *= std::ldexp(1.0, -e);  // exact: a power of two in [2^-1024, 2^1021]
  return true;
}

/// The unsigned angle between \p a and \p b in [0, pi], as atan2(|a x b|, a . b); 0 if either
/// vector is zero (or below the smallest normal double). Each vector is first scaled by a power
/// of two into the working range (the angle does not depend on their lengths), so the products
/// neither overflow nor underflow for any finite input.
[[nodiscard]] inline double angle_between(Vec3 a, Vec3 b) noexcept {
  int ea = 0, eb = 0;
  if (!to_working_range(a, ea) || !to_working_range(b, eb)) return 0.0;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// The angle between a and b and its gradients: d angle / d a into \p ga and d angle / d b into
/// \p gb. Where the angle is not differentiable (a or b zero, a parallel to b) both are zero.
/// Scaled into the working range like angle_between(); the gradients are scaled back
/// (d angle / d a scales as 1 / |a|), and they are finite for every vector that is not counted
/// as zero.
inline double angle_gradient(Vec3 a, Vec3 b, Vec3& ga, Vec3& gb) noexcept {
  int ea = 0, eb = 0;
  if (!to_working_range(a, ea) || !to_working_range(b, eb)) {
    ga.setZero();
    gb.setZero();
    return 0.0;
  }
  const Vec3 n = a.cross(b);
  const double s = n.norm(), c = a.dot(b);
  const double theta = std::atan2(s, c);
  const double aa = a.squaredNorm(), bb = b.squaredNorm();
  if (!(s > 0.0) || !(aa > 0.0) || !(bb > 0.0)) {
    ga.setZero();
    gb.setZero();
    return theta;
  }
  // theta grows when a turns away from b in their common plane: d theta / d a = -(n^ x a)/|a|^2,
  // d theta / d b = (n^ x b)/|b|^2, with n^ the unit normal a x b / |a x b|.
  const Vec3 nh = n / s;
  ga = -nh.cross(a) / aa;
  gb = nh.cross(b) / bb;
  // a was divided by 2^ea, so d theta / d a_original = d theta / d a_scaled * 2^-ea.
  if (ea != 0) ga *= std::ldexp(1.0, -ea);
  if (eb != 0) gb *= std::ldexp(1.0, -eb);
  return theta;
}

/// winding() without checks: \p n >= 0 vertices at \p x.
[[nodiscard]] inline double winding_unchecked(const Vec3* x, std::size_t n,
                                              const Vec3& p) noexcept {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) sum += angle_between(x[i] - p, x[i + 1] - p);
  return sum / two_pi;
}

/// winding_gradient() without checks: writes d w / d x_i into g[i] (n entries) and returns w.
inline double winding_gradient_unchecked(const Vec3* x, std::size_t n, const Vec3& p,
                                         Vec3* g) noexcept {
  for (std::size_t i = 0; i < n; ++i) g[i].setZero();
  double sum = 0.0;
  Vec3 ga, gb;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    sum += angle_gradient(x[i] - p, x[i + 1] - p, ga, gb);
    g[i] += ga / two_pi;
    g[i + 1] += gb / two_pi;
  }
  return sum / two_pi;
}

template <PointRange R>
void require_curve(const R& points, const Vec3& p, std::string_view name = "points") {
  if (std::ranges::size(points) < 2)
    throw_invalid_argument(
        name, "expected at least 2 points, got " + std::to_string(std::ranges::size(points)));
  std::size_t i = 0;
  for (const Eigen::Vector3d& x : points) {
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(x[k]))
        throw_invalid_argument(name,
                               "expected finite points, point " + std::to_string(i) + " is not");
    ++i;
  }
  require_finite(p, "p");
  i = 0;
  for (const Eigen::Vector3d& x : points) {
    if (!(x - p).allFinite())
      throw_invalid_argument(name, "point " + std::to_string(i) +
                                       " minus p overflows (each coordinate of X_i - p must stay "
                                       "within the double range, about 1.8e308)");
    ++i;
  }
}

}  // namespace detail

/// The winding of the piecewise-linear curve through \p points around \p p (paper III.A).
///
/// \f$ w = \frac{1}{2\pi} \sum_{i=0}^{n-2} \angle(X_i - p, X_{i+1} - p) \f$, each angle in
/// [0, pi] computed as atan2(|a x b|, a . b), which is accurate for small and nearly straight
/// angles alike. The curve is open: to close it, repeat the first point at the end. For a closed
/// planar curve through p's plane that winds monotonically k times around p, w = k; for a general
/// curve w >= 0 measures how far the curve wraps around p. w is invariant under rotations,
/// translations and uniform scalings about p, unchanged by reversing the curve, and additive
/// under concatenation.
///
/// Degenerate cases: a vertex at p contributes no angle to either of its segments (so w stays
/// finite; the curve passing through p is where w jumps). A zero-length segment contributes 0.
///
/// Range: w is finite and scale-invariant over the whole finite double range. Each X_i - p is
/// brought to unit size by an exact power of two before the cross and dot products (vectors whose
/// largest coordinate lies in [2^-250, 2^250] are used as they are), so a curve scaled by any
/// factor from 1e-300 to 1e300 gives the same w to rounding. A vertex whose largest coordinate
/// of X_i - p is below the smallest normal double (2.2e-308) counts as a vertex at p.
///
/// \param[in] points the vertices X_0..X_{n-1} (m), any contiguous range of Eigen::Vector3d
/// \param[in] p the reference point (m), e.g. an object's centre of mass
/// \return w (turns; dimensionless)
/// \throws topograsp::invalid_argument naming "points" if there are fewer than 2 points, a
///         point is not finite or a difference X_i - p overflows (finite points more than
///         1.8e308 apart), naming "p" if p is not finite.
template <PointRange R>
[[nodiscard]] double winding(const R& points, const Eigen::Vector3d& p) {
  detail::require_curve(points, p);
  return detail::winding_unchecked(std::ranges::data(points), std::ranges::size(points), p);
}

/// The winding of the curve through \p points around \p p, with its exact gradient with respect
/// to every vertex: gradient[i] = d w / d X_i (1/m). The gradient with respect to p is
/// -sum_i gradient[i] (w depends on X_i - p only).
///
/// Where w is not differentiable (a vertex at p, two consecutive vertices in line with p) the
/// terms of the affected angle are zero, a valid one-sided choice; everywhere else the gradient
/// is exact. The gradient scales as 1 / scale (a curve scaled by s about p has gradient / s) and
/// is finite for every accepted input: each term is computed at unit size and scaled back by an
/// exact power of two, and a term is at most about 1 / |X_i - p| <= 1 / 2.2e-308.
///
/// \throws topograsp::invalid_argument as winding(), and naming "gradient" if its size differs
///         from the number of points.
template <PointRange R>
double winding_gradient(const R& points, const Eigen::Vector3d& p,
                        std::span<Eigen::Vector3d> gradient) {
  detail::require_curve(points, p);
  if (gradient.size() != std::ranges::size(points))
    detail::throw_invalid_argument(
        "gradient", "expected " + std::to_string(std::ranges::size(points)) + " entries, got " +
                        std::to_string(gradient.size()));
  return detail::winding_gradient_unchecked(std::ranges::data(points), std::ranges::size(points), p,
                                            gradient.data());
}

}  // namespace topograsp
