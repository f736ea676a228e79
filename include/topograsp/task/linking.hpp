// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Gauss linking integral of two straight segments in closed form (with its gradient), the
/// linking number of two closed polylines and the writhe matrix of two open ones.
#pragma once

#include <array>
#include <cmath>
#include <string>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/task/winding.hpp>

namespace topograsp {

namespace detail {

/// The signed solid angle of the triangle (a, b, c) seen from the origin, 2 atan2(N, D) with
/// N = a . (b x c) and D = |a||b||c| + (a.b)|c| + (a.c)|b| + (b.c)|a| (Van Oosterom and
/// Strackee 1983), and its gradients with respect to a, b, c (zero where a vertex is at the
/// origin, where the angle jumps).
inline double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, Vec3* ga, Vec3* gb,
                                   Vec3* gc) noexcept {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  if (!(la > 0.0) || !(lb > 0.0) || !(lc > 0.0)) {
    if (ga) ga->setZero(), gb->setZero(), gc->setZero();
    return 0.0;
  }
  const Vec3 bc = b.cross(c);
  const double N = a.dot(bc);
  const double ab = a.dot(b), ac = a.dot(c), bcd = b.dot(c);
  const double D = la * lb * lc + ab * lc + ac * lb + bcd * la;
  const double omega = 2.0 * std::atan2(N, D);
  if (ga) {
    const double den = N * N + D * D;
    if (!(den > 0.0)) {
      ga->setZero(), gb->setZero(), gc->setZero();
      return omega;
    }
    const double kN = 2.0 * D / den, kD = -2.0 * N / den;
    const Vec3 ua = a / la, ub = b / lb, uc = c / lc;
    *ga = kN * bc + kD * (ua * (lb * lc + bcd) + b * lc + c * lb);
    *gb = kN * c.cross(a) + kD * (ub * (la * lc + ac) + a * lc + c * la);
    *gc = kN * a.cross(b) + kD * (uc * (la * lb + ab) + a * lb + b * la);
  }
  return omega;
}

}  // namespace detail

/// The Gauss linking integral of the segments p1 -> p2 and p3 -> p4, in closed form:
/// \f[ w = \frac{1}{4\pi} \int_0^1\!\!\int_0^1
///     \frac{(r_a - r_b) \cdot (\dot r_a \times \dot r_b)}{|r_a - r_b|^3}\, ds\, dt, \f]
/// which is the signed solid angle, over 4 pi, of the parallelogram p3 - p1, p4 - p1, p4 - p2,
/// p3 - p2 swept by r_b - r_a (computed as two triangles by Van Oosterom and Strackee's formula,
/// with atan2). Writes dw/dp_k into g[k] if \p g is not null. Segments that meet contribute 0
/// (the integral jumps there).
inline double segment_linking(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4,
                              std::array<Vec3, 4>* g = nullptr) noexcept {
  const Vec3 r13 = p3 - p1, r14 = p4 - p1, r24 = p4 - p2, r23 = p3 - p2;
  constexpr double k = -1.0 / (4.0 * pi);
  if (g == nullptr)
    return k * (detail::triangle_solid_angle(r13, r14, r24, nullptr, nullptr, nullptr) +
                detail::triangle_solid_angle(r13, r24, r23, nullptr, nullptr, nullptr));
  Vec3 a1, b1, c1, a2, b2, c2;
  const double omega = detail::triangle_solid_angle(r13, r14, r24, &a1, &b1, &c1) +
                       detail::triangle_solid_angle(r13, r24, r23, &a2, &b2, &c2);
  // d/d r13 = a1 + a2, d/d r14 = b1, d/d r24 = c1 + b2, d/d r23 = c2.
  const Vec3 g13 = a1 + a2, g14 = b1, g24 = c1 + b2, g23 = c2;
  (*g)[0] = -k * (g13 + g14);
  (*g)[1] = -k * (g24 + g23);
  (*g)[2] = k * (g13 + g23);
  (*g)[3] = k * (g14 + g24);
  return k * omega;
}

/// The Gauss linking number of two closed polylines: each is closed by the segment from its
/// last point back to its first. Sum of segment_linking() over all pairs of segments; an
/// integer (up to rounding) when the curves do not meet. Positive for a right-handed (positive)
/// Hopf link.
/// \throws topograsp::invalid_argument naming "a" or "b" for fewer than 2 points or a non-finite
///         point.
template <PointRange A, PointRange B>
[[nodiscard]] double linking_number(const A& a, const B& b) {
  detail::require_curve(a, Vec3::Zero(), "a");
  detail::require_curve(b, Vec3::Zero(), "b");
  const Vec3* x = std::ranges::data(a);
  const Vec3* y = std::ranges::data(b);
  const std::size_t n = std::ranges::size(a), m = std::ranges::size(b);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < m; ++j)
      sum += segment_linking(x[i], x[(i + 1) % n], y[j], y[(j + 1) % m]);
  return sum;
}

/// The writhe matrix of two open polylines (Ho and Komura 2009): entry (i, j) is the Gauss
/// linking integral segment_linking() of segment i of \p a and segment j of \p b; its sum is the
/// total writhe between the curves (the linking number, for closed curves listed with their
/// first point repeated at the end). Allocates its result; see WritheTask for the hot path.
/// \throws topograsp::invalid_argument naming "a" or "b" as linking_number().
template <PointRange A, PointRange B>
[[nodiscard]] MatX writhe_matrix(const A& a, const B& b) {
  detail::require_curve(a, Vec3::Zero(), "a");
  detail::require_curve(b, Vec3::Zero(), "b");
  const Vec3* x = std::ranges::data(a);
  const Vec3* y = std::ranges::data(b);
  const auto n = static_cast<Eigen::Index>(std::ranges::size(a)) - 1;
  const auto m = static_cast<Eigen::Index>(std::ranges::size(b)) - 1;
  MatX W(n, m);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < m; ++j) W(i, j) = segment_linking(x[i], x[i + 1], y[j], y[j + 1]);
  return W;
}

}  // namespace topograsp
