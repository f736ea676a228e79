// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Fingertip mapping (Rohling and Hollerbach 1993): the target hand's fingertips fitted by bounded
/// least squares to the source's, scaled to the target's size and put on the object's surface.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <topograsp/grasp/transfer/common.hpp>
#include <topograsp/kinematics/least_squares.hpp>

namespace topograsp {

/// The largest distance (m) between a fitted fingertip and its target for which the fingertip
/// mapping counts as done: 0.5 m, about three times the SDH's finger length (0.17 m). A larger
/// error means the targets were out of the hand's reach, and the fit failed.
inline constexpr double k_fingertip_max_error = 0.5;

/// The finger correspondence of the fingertip mapping to hand \p Target from a source hand of
/// \p source_fingers fingers whose thumb is finger \p source_thumb: for each finger of Target
/// (its hand description's order), the source finger whose tip its tip is fitted to, or -1. The
/// thumb goes to the thumb; Target's other fingers, the j-th of its n in order, to the
/// floor(j m / n)-th of the source's m other fingers, each source finger used once (a Target
/// finger whose source finger is already taken is left out of the fit and closes with the hand).
/// From the human hand (index, middle, ring, little): the SDH's and the Barrett's two fingers get
/// the index and the ring; the Allegro's and the LEAP hand's three the index, middle and ring; the
/// Shadow hand's four their namesakes. The rule was stated before any run.
/// \throws topograsp::invalid_argument naming "source_fingers" for fewer than two source fingers,
/// "source_thumb" for a thumb that is not one of them.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] constexpr std::array<int, Target.fingers.size()> fingertip_correspondence(
    int source_fingers, int source_thumb) {
  if (source_fingers < 2)
    detail::throw_invalid_argument("source_fingers", "expected at least 2 (a thumb and a finger)");
  if (source_thumb < 0 || source_thumb >= source_fingers)
    detail::throw_invalid_argument("source_thumb", "expected one of the source's fingers");
  constexpr int n = static_cast<int>(Target.fingers.size()) - 1;
  const int m = source_fingers - 1;
  std::array<int, Target.fingers.size()> c{};
  int j = 0, last = -1;
  for (int f = 0; f <= n; ++f) {
    auto& to = c[static_cast<std::size_t>(f)];
    if (f == Target.thumb) {
      to = source_thumb;
      continue;
    }
    const int k = j++ * m / n;  // the k-th of the source's fingers other than its thumb
    to = k == last ? -1 : (k < source_thumb ? k : k + 1);
    last = k;
  }
  return c;
}

/// fingertip_correspondence from hand \p Source to hand \p Target.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] constexpr std::array<int, Target.fingers.size()> fingertip_correspondence() {
  return fingertip_correspondence<Target>(static_cast<int>(Source.fingers.size()), Source.thumb);
}

/// How many fingertips the fingertip mapping from \p Source to \p Target fits: the thumb and
/// min(n, m) others.
template <const auto& Target, const auto& Source>
inline constexpr int fingertip_count =
    1 + static_cast<int>(std::min(Target.fingers.size(), Source.fingers.size())) - 1;

namespace detail {

// The fitted pairs of the fingertip mapping from source (fingertip_correspondence): {Target
// finger, source finger}, the thumb first, then Target's fingers in order.
template <const auto& Target>
std::vector<std::pair<int, int>> fingertip_pairs(const SourceGrasp& source) {
  const auto c =
      fingertip_correspondence<Target>(static_cast<int>(source.digits.size()), source.thumb);
  std::vector<std::pair<int, int>> pairs{{Target.thumb, source.thumb}};
  for (int f = 0; f < static_cast<int>(c.size()); ++f)
    if (f != Target.thumb && c[static_cast<std::size_t>(f)] >= 0)
      pairs.emplace_back(f, c[static_cast<std::size_t>(f)]);
  return pairs;
}

// The radius (m) of finger f's tip: of the shapes of its tip's link, the one nearest the tip
// point; its radius (sphere, capsule, cylinder) or smallest half extent (box). 0 if the link has
// no shape.
template <const auto& M>
double tip_radius(int f) {
  KinematicsData<M> d;
  forward_kinematics(d, Vec<M.nq>::Zero());
  const LinkPoint tip = finger_tip<M>(f);
  const Primitive probe = Primitive::sphere(world_point(d, tip), 1e-6);
  double nearest = std::numeric_limits<double>::infinity(), radius = 0.0;
  for (std::size_t k = 0; k < M.n_shapes; ++k) {
    const Shape& s = M.shapes[k];
    if (s.link != tip.link) continue;
    const double distance = std::abs(signed_distance(world_shape(d, k), probe).distance);
    if (distance >= nearest) continue;
    nearest = distance;
    const auto& size = s.spec.size;
    radius = s.spec.type == ShapeType::box ? std::min({size[0], size[1], size[2]}) : size[0];
  }
  return radius;
}

// Hand M's free-base configuration (FreeBase) with its grasp frame (hand_profile) at T (object
// frame, grasp_frame's convention: z the approach, x up) and joints q.
template <const auto& M>
Vec<FreeBase<M>::model.nq> free_at_grasp_frame(const Eigen::Isometry3d& T, const Vec<M.nq>& q) {
  constexpr auto& F = FreeBase<M>::model;
  const HandProfile<M> profile = hand_profile<M>();
  Eigen::Isometry3d frame = T;
  frame.linear() =
      T.linear() * palm_rotation(profile.axes, gripper_hand_axes.approach, gripper_hand_axes.up);
  return place_frame<F>(
      frame, F.find_frame(M.frames[static_cast<std::size_t>(profile.frame)].spec.name.view()), q);
}

}  // namespace detail

/// The size of hand \p Target over the source hand of \p source for the fingertip mapping: the
/// summed lengths of the fitted digits held straight (fingertip_correspondence; a digit from the
/// first link that moves it alone out to its tip). Human -> SDH: 0.5145 / 0.2366 = 2.175; infinite
/// if the source's fitted digits have no length.
/// \throws topograsp::invalid_argument naming "source" for a source that unusable_source refuses.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] double fingertip_scale(const SourceGrasp& source) {
  if (std::string unusable = unusable_source(source); !unusable.empty())
    detail::throw_invalid_argument("source", unusable);
  double target = 0.0, from = 0.0;
  for (const auto& [t, s] : detail::fingertip_pairs<Target>(source)) {
    target += detail::digit_length<Target>(t);
    from += source.digits[static_cast<std::size_t>(s)].length;
  }
  return target / from;
}

/// fingertip_scale from hand \p Source to hand \p Target.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] double fingertip_scale() {
  return fingertip_scale<Target>(describe_source(HandGrasp<Source>{}));
}

/// The targets of the fingertip mapping (object frame), the thumb's first, then Target's fitted
/// fingers in order (fingertip_correspondence): the tips of their source fingers in \p source
/// scaled about their centroid by options.fingertip_scale (0: fingertip_scale<Target>(source)),
/// then each moved to the nearest point of the object's surface and out along its normal by the
/// radius of Target's fingertip and options.sim.contact_gap, so that the fitted tips touch the
/// object, not the air. A scaled tip farther than k_fingertip_max_error from the centroid (a scale
/// far beyond any hand's, or one that overflows) is left where it is, for the fit to refuse.
/// \throws topograsp::invalid_argument naming "source" for a source that unusable_source refuses.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] std::vector<Vec3> fingertip_targets(const GraspObject& object,
                                                  const SourceGrasp& source,
                                                  const TransferOptions& options = {}) {
  if (std::string unusable = unusable_source(source); !unusable.empty())
    detail::throw_invalid_argument("source", unusable);
  const auto pairs = detail::fingertip_pairs<Target>(source);
  std::vector<Vec3> goal(pairs.size());
  Vec3 centroid = Vec3::Zero();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    goal[k] = source.root * source.digits[static_cast<std::size_t>(pairs[k].second)].tip;
    centroid += goal[k];
  }
  centroid /= static_cast<double>(pairs.size());
  const double scale =
      options.fingertip_scale > 0.0 ? options.fingertip_scale : fingertip_scale<Target>(source);
  const Composite shape = object.composite();  // parts() views it: keep it alive
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    Vec3& p = goal[k];
    p = centroid + scale * (p - centroid);
    if (!p.allFinite() || (p - centroid).norm() > k_fingertip_max_error) continue;
    const Contact c = detail::nearest_surface(shape, p);
    p = c.point_a +
        (detail::tip_radius<Target>(pairs[k].first) + options.sim.contact_gap) * c.normal;
  }
  return goal;
}

namespace detail {

// The fingertip fit of fingertip_grasp with its N fitted pairs known at compile time (the fit's
// matrices are fixed-size): Target's fingertips pairs[k].first fitted to goal[k].
template <const auto& Target, int N>
HandTransfer<Target> fingertip_fit(TransferRun<Target>& run, const GraspObject& object,
                                   const SourceGrasp& source,
                                   const std::vector<std::pair<int, int>>& pairs,
                                   const std::vector<Vec3>& goal, double scale,
                                   const TransferOptions& options,
                                   const SecondJudge<Target>& second) {
  constexpr auto& F = FreeBase<Target>::model;
  constexpr int rows = 3 * N + F.nq;
  Vec<F.nq> q = free_at_grasp_frame<Target>(source.grasp_frame, base_preshape<Target>(options));
  const Vec<F.nq> lo = lower_limits<F>(), hi = upper_limits<F>();
  // Residual: the tip errors (m), then a weak pull toward the transplant pose and the pre-shape
  // (weight options.fingertip_prior per m or rad), which keeps the under-determined fit (more
  // unknowns than equations) from drifting.
  const Vec<F.nq> q_ref = q;
  const double w = std::sqrt(options.fingertip_prior);
  KinematicsData<F> d;
  const auto tip = [&](int k) { return finger_tip<F>(pairs[static_cast<std::size_t>(k)].first); };
  const auto residual = [&](const Vec<F.nq>& x, Vec<rows>& e) {
    forward_kinematics(d, x);
    for (int k = 0; k < N; ++k)
      e.template segment<3>(3 * k) = world_point(d, tip(k)) - goal[static_cast<std::size_t>(k)];
    e.template tail<F.nq>() = w * (x - q_ref);
    return e.squaredNorm();
  };
  Vec<rows> e;
  double cost = residual(q, e);
  if (!std::isfinite(cost)) {
    char buf[128];
    std::snprintf(buf, sizeof buf,
                  "the fingertip fit's cost is not finite (fingertip targets out of range, "
                  "scale %g)",
                  scale);
    return run.unplanned(buf);
  }
  Mat<rows, F.nq> J = Mat<rows, F.nq>::Zero();
  J.template bottomRows<F.nq>() = w * Mat<F.nq, F.nq>::Identity();
  BoundedLeastSquaresOptions lm;
  lm.iterations = options.fingertip_iterations;
  lm.settled = 1e-12;
  const BoundedLeastSquaresResult fit = bounded_least_squares(
      q, e, cost, lo, hi, residual,
      [&](Mat<rows, F.nq>& Jt) {
        for (int k = 0; k < N; ++k)
          Jt.template middleRows<3>(3 * k) = point_jacobian(d, tip(k).link, world_point(d, tip(k)));
      },
      J, lm);
  if (fit.accepted == 0)
    return run.unplanned(
        "the fingertip fit accepted no step (the hand would stay at the transplant pose)");
  forward_kinematics(d, q);
  double tip_error = 0.0;
  for (int k = 0; k < N; ++k)
    tip_error =
        std::max(tip_error, (world_point(d, tip(k)) - goal[static_cast<std::size_t>(k)]).norm());
  if (!(tip_error <= k_fingertip_max_error)) {
    char buf[128];
    std::snprintf(buf, sizeof buf,
                  "the fingertip fit did not reach the targets (largest tip error %g m, more "
                  "than %g m)",
                  tip_error, k_fingertip_max_error);
    return run.unplanned(buf);
  }
  const Eigen::Isometry3d fitted = link_pose(d, F.find_link(Target.links[0].spec.name.view()));
  const Vec<Target.nq> q_hand = q.template tail<Target.nq>();
  if (std::string unusable = unusable_hand_pose<Target>(fitted, q_hand); !unusable.empty())
    return run.unplanned("fitted: " + unusable);
  return run.open_place_and_judge(object, fitted, q_hand, options, second);
}

}  // namespace detail

/// Fingertip mapping (Rohling and Hollerbach 1993) from any hand to any hand: Target's fingertips
/// (fingertip_correspondence: the thumb to the thumb, the fingers spread over the source's) fitted
/// to fingertip_targets, the source's tips scaled to Target's size and put on the object's
/// surface. Target on its free base is fitted by damped least squares, within its joint limits,
/// started at the transplant pose (its grasp frame at the source's, joints base_preshape) with a
/// weak pull toward it (options.fingertip_prior); then opened until clear of the object
/// (open_hand_until_clear), backed off along its approach only if it still overlaps, or moved on
/// until contact (at most final_approach), closed until contact and judged (with \p second if
/// set).
///
/// When the fit cannot be done the result is not planned (planned false, nothing simulated) and
/// reason says why: a source that unusable_source refuses, a source whose fitted digits have no
/// length, a fit whose cost is not finite
/// (fingertip targets so far apart that their squared errors overflow, e.g. fingertip_scale =
/// 1e300), a fit whose fingertips end more than k_fingertip_max_error from their targets (targets
/// out of the hand's reach, e.g. fingertip_scale = 1e10), or a fitted hand that HandScene cannot
/// take. It never reports the transplant pose it starts from as a fingertip transfer.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] HandTransfer<Target> fingertip_grasp(const GraspObject& object,
                                                   const SourceGrasp& source,
                                                   const TransferOptions& options = {},
                                                   const SecondJudge<Target>& second = {}) {
  detail::TransferRun<Target> run(TransferMethod::fingertip, unusable_source(source), options);
  if (run.refused()) return run.unplanned();
  const auto pairs = detail::fingertip_pairs<Target>(source);
  const double scale =
      options.fingertip_scale > 0.0 ? options.fingertip_scale : fingertip_scale<Target>(source);
  if (!std::isfinite(scale))
    return run.unplanned("the source's fitted digits have no length (no fingertip scale)");
  const auto goal = fingertip_targets<Target>(object, source, options);
  // The fit, for its number of pairs: 2 (the thumb and one finger) to Target's finger count.
  std::optional<HandTransfer<Target>> r;
  [&]<int... K>(std::integer_sequence<int, K...>) {
    (void)((pairs.size() == K + 2 &&
            (r.emplace(detail::fingertip_fit<Target, K + 2>(run, object, source, pairs, goal, scale,
                                                            options, second)),
             true)) ||
           ...);
  }(std::make_integer_sequence<int, static_cast<int>(Target.fingers.size()) - 1>{});
  if (!r) return run.unplanned("the source gives no fingertip pairs to fit");  // unreachable
  return std::move(*r);
}

}  // namespace topograsp
