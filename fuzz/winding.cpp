// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: winding() and winding_gradient() (task/winding.hpp).
//
// Mode 0, any finite curve and point (every coordinate from the whole double range): w is finite
// and in [0, (n - 1) / 2] (each segment adds an angle in [0, pi]), the gradient is finite, and both
// entry points agree on w; or topograsp::invalid_argument, only if some X_i - p overflows.
// Mode 1, a curve and point in [-1, 1]^3, scaled by 10^k (k in [-300, 300]) and translated by up
// to 1e3 (in the curve's units): w is unchanged within a bound derived from the rounding of the
// inputs (the angle between a and b moves by at most |da| / |a| when a moves by da), and where the
// configuration is well conditioned the gradient scales as 1 / 10^k.

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <span>
#include <string>

#include <topograsp/core/error.hpp>
#include <topograsp/task/winding.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::Vec3;
using namespace topograsp::fuzz;

constexpr int max_points = 12;
constexpr double eps = std::numeric_limits<double>::epsilon();

struct Curve {
  std::array<Vec3, max_points> x;
  int n = 0;
  [[nodiscard]] std::span<const Vec3> points() const {
    return {x.data(), static_cast<std::size_t>(n)};
  }
};

std::string describe(const Curve& c, const Vec3& p) {
  std::string s = "n = " + std::to_string(c.n) + "\n";
  for (int i = 0; i < c.n; ++i)
    s += "x[" + std::to_string(i) + "] = " + vec_str(c.x[static_cast<std::size_t>(i)]) + "\n";
  return s + "p = " + vec_str(p) + "\n";
}

struct Result {
  double w = 0.0, wg = 0.0;
  std::array<Vec3, max_points> g;
};

Result evaluate(const Curve& c, const Vec3& p) {
  Result r;
  r.w = topograsp::winding(c.points(), p);
  r.wg = topograsp::winding_gradient(c.points(), p,
                                     std::span<Vec3>(r.g.data(), static_cast<std::size_t>(c.n)));
  return r;
}

// Checks every property that holds for one evaluation on its own.
void check_alone(const Curve& c, const Result& r, const std::string& input, const char* which) {
  const std::string at = std::string(" (") + which + ")";
  if (!std::isfinite(r.w)) fuzz_fail("winding", "w = " + num(r.w) + " is not finite" + at, input);
  if (!(r.w >= 0.0 && r.w <= 0.5 * (c.n - 1) * (1.0 + 1e-12)))
    fuzz_fail("winding", "w = " + num(r.w) + " is outside [0, (n - 1) / 2]" + at, input);
  if (!(std::abs(r.wg - r.w) <= 1e-12 * (1.0 + c.n)))
    fuzz_fail("winding", "winding() = " + num(r.w) + " but winding_gradient() = " + num(r.wg) + at,
              input);
  for (int i = 0; i < c.n; ++i)
    if (!r.g[static_cast<std::size_t>(i)].allFinite())
      fuzz_fail("winding",
                "gradient[" + std::to_string(i) +
                    "] = " + vec_str(r.g[static_cast<std::size_t>(i)]) + " is not finite" + at,
                input);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    FuzzInput in(data, size);
    const int mode = in.integer(0, 1);
    Curve c;
    c.n = in.integer(2, max_points);
    Vec3 p;
    if (mode == 0) {
      for (int i = 0; i < c.n; ++i) {
        const double a = in.any_finite(), b = in.any_finite(), d = in.any_finite();
        c.x[static_cast<std::size_t>(i)] = Vec3(a, b, d);
      }
      const double a = in.any_finite(), b = in.any_finite(), d = in.any_finite();
      p = Vec3(a, b, d);
      const std::string input = describe(c, p);
      Result r;
      try {
        r = evaluate(c, p);
      } catch (const topograsp::invalid_argument& e) {
        // winding() may refuse points whose offset from p overflows (documented); only those.
        bool overflows = false;
        for (int i = 0; i < c.n; ++i)
          overflows = overflows || !(c.x[static_cast<std::size_t>(i)] - p).allFinite();
        if (!overflows)
          fuzz_fail("winding",
                    std::string("refused finite points whose offsets are finite: ") + e.what(),
                    input);
        return;
      }
      check_alone(c, r, input, "as given");
      return;
    }

    for (int i = 0; i < c.n; ++i) c.x[static_cast<std::size_t>(i)] = in.vec(-1.0, 1.0);
    p = in.vec(-1.0, 1.0);
    const int k = in.integer(-300, 300);
    const double s = std::pow(10.0, k);
    const Vec3 t = in.vec(-1.0, 1.0) * std::pow(10.0, in.integer(-3, 3));
    const std::string input =
        describe(c, p) + "scale = 1e" + std::to_string(k) + "\ntranslation = " + vec_str(t) + "\n";

    Curve cs = c, ct = c;
    for (int i = 0; i < c.n; ++i) {
      const auto u = static_cast<std::size_t>(i);
      cs.x[u] = s * c.x[u];
      ct.x[u] = c.x[u] + t;
    }
    const Vec3 ps = s * p, pt = p + t;
    const Result r0 = evaluate(c, p), rs = evaluate(cs, ps), rt = evaluate(ct, pt);
    check_alone(c, r0, input, "as given");
    check_alone(cs, rs, input, "scaled");
    check_alone(ct, rt, input, "translated");

    // The bound: vertex i moves relative to p by at most d_i (rounding of the scaled or translated
    // coordinates and of their difference, with a factor 4 to spare; the subnormal spacing where
    // the scaled values underflow), which turns each of its (one or two) angles by at most d_i /
    // r_i.
    double inv_sum = 0.0, tol_s = 0.0, tol_t = 0.0;
    bool vertex_at_p = false;
    for (int i = 0; i < c.n; ++i) {
      const Vec3& xi = c.x[static_cast<std::size_t>(i)];
      const double r = (xi - p).norm();
      // A vertex at p, or (scaled) nearer to it than the smallest normal double, which winding()
      // may count as at p (its documented degenerate case): w jumps there.
      const double scaled_offset = s * (xi - p).cwiseAbs().maxCoeff();
      if (!(r > 0.0) || !(scaled_offset > 4.0 * std::numeric_limits<double>::min())) {
        vertex_at_p = true;
        break;
      }
      const double segments = (i == 0 || i == c.n - 1) ? 1.0 : 2.0;
      const double base = xi.norm() + p.norm();
      const double ds = 16.0 * eps * base + 16.0 * std::numeric_limits<double>::denorm_min() / s;
      const double dt = 16.0 * eps * (base + 2.0 * t.norm());
      tol_s += segments * ds / r;
      tol_t += segments * dt / r;
      inv_sum += segments / r;
    }
    if (vertex_at_p) return;                   // w jumps there: nothing to compare
    const double rounding = 16.0 * eps * c.n;  // atan2 and the products, per angle
    tol_s = tol_s / (2.0 * std::numbers::pi) + rounding;
    tol_t = tol_t / (2.0 * std::numbers::pi) + rounding;
    if (!(std::abs(rs.w - r0.w) <= tol_s))
      fuzz_fail("winding",
                "scaled: w = " + num(rs.w) + ", unscaled: w = " + num(r0.w) + " (tolerance " +
                    num(tol_s) + ")",
                input);
    if (!(std::abs(rt.w - r0.w) <= tol_t))
      fuzz_fail("winding",
                "translated: w = " + num(rt.w) + ", as given: w = " + num(r0.w) + " (tolerance " +
                    num(tol_t) + ")",
                input);

    // The gradient scales as 1 / s where every angle is well away from 0 and pi (where its
    // gradient's direction is ill-conditioned) and every vertex well away from p.
    for (int i = 0; i + 1 < c.n; ++i) {
      const Vec3 a = c.x[static_cast<std::size_t>(i)] - p,
                 b = c.x[static_cast<std::size_t>(i + 1)] - p;
      if (!(a.norm() > 1e-3 && b.norm() > 1e-3 && a.cross(b).norm() > 1e-3 * a.norm() * b.norm()))
        return;
    }
    for (int i = 0; i < c.n; ++i) {
      const auto u = static_cast<std::size_t>(i);
      const Vec3 scaled_back = rs.g[u] * s;
      if (!((scaled_back - r0.g[u]).norm() <= 1e-6 * inv_sum))
        fuzz_fail("winding",
                  "gradient[" + std::to_string(i) + "]: scaled back " + vec_str(scaled_back) +
                      ", unscaled " + vec_str(r0.g[u]),
                  input);
    }
  });
}
