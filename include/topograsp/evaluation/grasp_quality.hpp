// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Ferrari-Canny epsilon (Q1) of a grasp, as GraspIt's QualEpsilon computes it on its "L1
/// Norm" grasp wrench space: the convex hull (qhull) of every contact's friction-cone edge
/// wrenches, each with a unit normal force, and epsilon the smallest distance from the origin to a
/// facet of that hull. Needs qhull's reentrant C library (Debian libqhull-dev, CMake target
/// Qhull::qhull_r; in this project the target topograsp_qhull, which defines
/// TOPOGRASP_HAVE_QHULL): the core library does not depend on it. Including this header brings in
/// qhull's C macros (True, False, boolT, FORALLfacets, ...). See docs/evaluation.md.
/// Both ferrari_canny_epsilon overloads are templates with nothing to give, instantiated only where
/// they are called (docs/architecture.md, "Compile time").
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include <topograsp/evaluation/grasp_wrench.hpp>

#include <libqhull_r/libqhull_r.h>  // declares its functions extern "C" itself

// qhull's hull area and volume (geom_r.h), declared here: geom_r.h defines macros named dX, dY,
// dZ and dW that would reach every file including this header.
extern "C" void qh_getarea(qhT* qh, facetT* facetlist);

namespace topograsp {

/// What the grasp wrench space says about a grasp.
enum class GraspQualityStatus : std::uint8_t {
  force_closure,      ///< the origin is strictly inside the hull: epsilon > 0
  not_force_closure,  ///< the hull is full but the origin is outside or on it: epsilon <= 0
  degenerate,         ///< no 6-D hull (fewer than 7 affinely independent wrenches): epsilon = 0
};

/// The status's name ("force_closure", "not_force_closure", "degenerate").
[[nodiscard]] constexpr std::string_view to_string(GraspQualityStatus s) noexcept {
  switch (s) {
    case GraspQualityStatus::force_closure:
      return "force_closure";
    case GraspQualityStatus::not_force_closure:
      return "not_force_closure";
    case GraspQualityStatus::degenerate:
      return "degenerate";
  }
  return "unknown";
}

/// The Ferrari-Canny epsilon of a grasp and how it was obtained.
struct GraspQuality {
  /// The minimum over hull facets of the origin's signed distance to the facet's plane, positive
  /// inside: the radius of the largest origin-centred ball in the hull when the grasp is force
  /// closure (> 0). When the origin is outside the hull it is minus the largest distance of the
  /// origin beyond a facet plane (< 0; GraspIt returns -1 there); within
  /// k_boundary_tolerance of 0 it is 0 (the origin on the boundary); 0 when degenerate. In force
  /// units per unit total normal force (dimensionless), torques divided by the torque scale.
  double epsilon = 0.0;
  GraspQualityStatus status = GraspQualityStatus::degenerate;
  /// Why the hull is degenerate (empty otherwise), e.g. too few wrenches or qhull's message.
  std::string reason;
  /// The unit outward normal (force; torque / scale) of the facet nearest the origin: the
  /// direction of the disturbance wrench the grasp resists least. Zero when degenerate.
  Vec<6> weakest_direction = Vec<6>::Zero();
  double volume = 0.0;  ///< the hull's 6-D volume (GraspIt's QualVolume); 0 when degenerate
  int wrenches = 0;     ///< the number of primitive wrenches (hull input points)
  int facets = 0;       ///< the number of hull facets (after qhull's merging)
  /// The qhull options that built the hull: k_qhull_epsilon_options (GraspIt's), or
  /// k_qhull_fallback_options when qhull gave up on those; empty when degenerate.
  std::string_view qhull_options;

  /// The origin counts as on the boundary (epsilon 0, not force closure) within this distance,
  /// well above rounding in wrenches of size about 1 and below any grasp worth the name.
  static constexpr double k_boundary_tolerance = 1e-9;
};

/// The qhull options of GraspIt's GWS::buildHyperplanesFromWrenches (src/gws.cpp): Pp (no
/// precision warnings), n (facet normals), Qx (exact pre-merges), C-0.0001 (pre-merge facets
/// whose centrums are within 1e-4 of each other).
inline constexpr std::string_view k_qhull_epsilon_options = "qhull Pp n Qx C-0.0001";

/// The qhull options tried when GraspIt's fail: QJ joggles the input by a tiny random amount
/// (about 1e-11 of the wrenches' size) so that every facet is a simplex and no merge is needed.
inline constexpr std::string_view k_qhull_fallback_options = "qhull Pp n QJ";

namespace detail {

/// One qhull run on \p wrenches with \p options: fills out.facets, out.volume and
/// out.weakest_direction, and \p epsilon with the smallest -offset over the facets; returns qhull's
/// exit code, and the first line of its error output in \p message (empty when it succeeded).
inline int run_qhull(const Eigen::Matrix<double, 6, Eigen::Dynamic>& wrenches,
                     std::string_view options, GraspQuality& out, double& epsilon,
                     std::string& message) {
  out.facets = 0;
  out.volume = 0.0;
  epsilon = std::numeric_limits<double>::infinity();
  // qhull's interface takes non-const arrays (it changes neither with these options).
  Eigen::Matrix<double, 6, Eigen::Dynamic> points = wrenches;
  std::string flags(options);
  char* err_text = nullptr;
  std::size_t err_size = 0;
  FILE* err = open_memstream(&err_text, &err_size);  // qhull's messages, kept, never printed
  qhT qh_state;
  qhT* qh = &qh_state;
  qh_zero(qh, err);
  const int exitcode = qh_new_qhull(qh, 6, static_cast<int>(points.cols()), points.data(), False,
                                    flags.data(), nullptr, err != nullptr ? err : stderr);
  if (exitcode == 0) {
    qh_getarea(qh, qh->facet_list);
    out.volume = qh->totvol;
    for (facetT* facet = qh->facet_list; facet != nullptr && facet->next != nullptr;
         facet = facet->next) {
      ++out.facets;
      // qhull: normal . x + offset = 0 on the facet, < 0 inside; the origin's signed distance
      // (positive inside) is -offset.
      if (-facet->offset < epsilon) {
        epsilon = -facet->offset;
        for (int d = 0; d < 6; ++d) out.weakest_direction[d] = facet->normal[d];
      }
    }
  }
  qh->NOerrexit = True;
  qh_freeqhull(qh, !qh_ALL);
  int curlong = 0, totlong = 0;
  qh_memfreeshort(qh, &curlong, &totlong);
  message.clear();
  if (err != nullptr) {
    std::fclose(err);
    if (err_text != nullptr && exitcode != 0) {
      const std::string_view text(err_text, err_size);
      message = text.substr(0, text.find('\n'));
    }
    std::free(err_text);
  }
  return exitcode;
}

}  // namespace detail

/// The Ferrari-Canny epsilon of the primitive wrenches \p wrenches (columns: force; torque divided
/// by the torque scale), e.g. from contact_wrenches(): the hull of their union (the L1 grasp
/// wrench space, total normal force <= 1). Fewer than 7 wrenches, an affine dimension below 6
/// (affine_dimension()) or a hull qhull cannot build give status degenerate, epsilon 0 and a
/// reason; never throws for that. qhull runs with GraspIt's options (k_qhull_epsilon_options);
/// when it fails on them it runs once more with joggled input (k_qhull_fallback_options), and
/// GraspQuality::qhull_options says which built the hull. Thread-safe (each call has its own qhull
/// state); allocates. Throws topograsp::invalid_argument naming "wrenches" for a non-finite entry.
template <class = void>
[[nodiscard]] GraspQuality ferrari_canny_epsilon(
    const Eigen::Matrix<double, 6, Eigen::Dynamic>& wrenches) {
  require_finite(wrenches, "wrenches");
  GraspQuality out;
  out.wrenches = static_cast<int>(wrenches.cols());
  if (wrenches.cols() < 7) {
    out.reason = std::to_string(wrenches.cols()) +
                 " wrenches: a 6-D hull needs at least 7 affinely independent ones";
    return out;
  }
  if (const int dim = affine_dimension(wrenches); dim < 6) {
    out.reason = "the wrenches span only " + std::to_string(dim) +
                 " of 6 dimensions: some disturbance (e.g. a torque about the line through two "
                 "contacts) meets no resistance";
    return out;
  }

  // GraspIt's options first; if qhull gives up on them (a "wide merge" precision error, e.g. with
  // 64 cone edges, whose wrenches lie on one ellipse per contact), joggled input.
  std::string message;
  double epsilon = std::numeric_limits<double>::infinity();
  int exitcode = 0;
  for (const std::string_view options : {k_qhull_epsilon_options, k_qhull_fallback_options}) {
    exitcode = detail::run_qhull(wrenches, options, out, epsilon, message);
    if (exitcode == 0 && out.facets > 0) {
      out.qhull_options = options;
      break;
    }
  }
  if (exitcode != 0 || out.facets == 0) {
    out.reason = "qhull could not build the hull (exit code " + std::to_string(exitcode) +
                 (message.empty() ? ")" : "): " + message);
    out.volume = 0.0;
    out.facets = 0;
    out.weakest_direction.setZero();
    return out;
  }
  if (epsilon > GraspQuality::k_boundary_tolerance) {
    out.status = GraspQualityStatus::force_closure;
    out.epsilon = epsilon;
  } else {
    out.status = GraspQualityStatus::not_force_closure;
    out.epsilon = epsilon < -GraspQuality::k_boundary_tolerance ? epsilon : 0.0;
  }
  return out;
}

/// The Ferrari-Canny epsilon (Q1) of a grasp by \p contacts (points, normals into the object,
/// friction coefficients), torques about \p centre (the object's centre of mass) divided by
/// \p torque_scale (m; GraspIt divides by the object's maxRadius, the largest distance from the
/// centre of mass to its surface: max_radius()), each friction cone linearised with
/// options.edges edges and a unit normal force (contact_wrenches()). See
/// ferrari_canny_epsilon(wrenches) for the result: a grasp with fewer than 7 affinely
/// independent wrenches (no contact, one or two contacts, frictionless contacts too few or
/// coplanar) is degenerate with epsilon 0, never an exception. Throws as contact_wrenches() for
/// bad input (a non-finite point, a zero normal, a negative friction, torque_scale <= 0, edges
/// < 3), naming the argument.
template <class = void>
[[nodiscard]] GraspQuality ferrari_canny_epsilon(std::span<const ContactForQuality> contacts,
                                                 const Vec3& centre, double torque_scale,
                                                 const QualityOptions& options = {}) {
  Eigen::Matrix<double, 6, Eigen::Dynamic> w;
  contact_wrenches(contacts, centre, torque_scale, options, w);
  return ferrari_canny_epsilon(w);
}

#if defined(TOPOGRASP_EXTERN_HAND_INDEPENDENT) && defined(TOPOGRASP_HAVE_QHULL)
// Compiled once, in the one translation unit that includes grasp/hand_independent.hpp (which
// compiles them where TOPOGRASP_HAVE_QHULL is defined, as here)
// (docs/benchmarks.md, "Compiling the transfer once per program").
extern template GraspQuality ferrari_canny_epsilon<void>(
    const Eigen::Matrix<double, 6, Eigen::Dynamic>&);
extern template GraspQuality ferrari_canny_epsilon<void>(std::span<const ContactForQuality>,
                                                         const Vec3&, double,
                                                         const QualityOptions&);
#endif

}  // namespace topograsp
