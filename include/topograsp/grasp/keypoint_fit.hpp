// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The human hand model fitted to a recorded grasp's 21 keypoints (io/keypoint_grasp.hpp): its
/// palm placed by the best rigid fit of the palm's keypoints (wrist, thumb CMC, the four finger
/// MCPs), then its free base and 20 joints fitted by damped least squares, within the joint
/// limits, to all 21 keypoints. The result is a source grasp for any transfer. The fit and the
/// demonstration are templates with nothing to give (`template <class = void>`), instantiated
/// only where they are called (docs/architecture.md, "Compile time").
#pragma once

#include <array>
#include <cmath>
#include <string_view>

#include <Eigen/SVD>

#include <topograsp/grasp/hand_grasp.hpp>
#include <topograsp/grasp/keypoints.hpp>
#include <topograsp/kinematics/jacobian.hpp>
#include <topograsp/kinematics/least_squares.hpp>

namespace topograsp {

/// The human hand fitted to keypoints, and how well.
struct KeypointFit {
  HandGrasp<models::human_hand> grasp;  ///< the palm's pose (object frame) and the 20 joints
  FitError error;                       ///< how far its keypoints are from the recording's
  int iterations = 0;                   ///< least-squares steps taken
};

/// A fit whose largest keypoint distance is over this (m) is worth a warning (grasp_transfer
/// prints one): 2 cm is a tenth of the model hand's length, what a hand 10 % larger or smaller
/// than the model leaves at its fingertips, while a file in the wrong units, frame or keypoint
/// order is off by decimetres or more.
inline constexpr double k_keypoint_fit_warning = 0.02;

namespace detail {

// The point of the human model (on its free base) that keypoint i stands for: a joint's origin,
// a fingertip frame, or the wrist (the palm's origin).
inline std::array<LinkPoint, keypoint_count> human_keypoint_points() {
  constexpr auto& F = models::human_hand_free;
  constexpr std::array<std::string_view, keypoint_count> names{
      "palm",       "thumb_cmc1", "thumb_mcp", "thumb_ip",   "thumb_tip",  "index_mcp",
      "index_pip",  "index_dip",  "index_tip", "middle_mcp", "middle_pip", "middle_dip",
      "middle_tip", "ring_mcp",   "ring_pip",  "ring_dip",   "ring_tip",   "pinky_mcp",
      "pinky_pip",  "pinky_dip",  "pinky_tip"};
  std::array<LinkPoint, keypoint_count> out{};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int link = F.find_link(names[i]);
    if (link >= 0) {
      out[i].link = link;
      continue;
    }
    const Frame& f = F.frames[static_cast<std::size_t>(F.find_frame(names[i]))];
    out[i].link = f.link;
    const Vec3 t = Pose(f.spec.offset).translation();
    out[i].offset = {t.x(), t.y(), t.z()};
  }
  return out;
}

// The rotation and translation that best map the points a onto b (least squares, Kabsch).
template <class = void>
Eigen::Isometry3d rigid_fit(std::span<const Vec3> a, std::span<const Vec3> b) {
  Vec3 ca = Vec3::Zero(), cb = Vec3::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    ca += a[i];
    cb += b[i];
  }
  ca /= static_cast<double>(a.size());
  cb /= static_cast<double>(b.size());
  Mat3 h = Mat3::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) h += (a[i] - ca) * (b[i] - cb).transpose();
  const Eigen::JacobiSVD<Mat3> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 d = Mat3::Identity();
  d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = svd.matrixV() * d * svd.matrixU().transpose();
  T.translation() = cb - T.linear() * ca;
  return T;
}

}  // namespace detail

/// The human hand model fitted to the keypoints of \p g: started from the palm's rigid fit with
/// the joints at zero (clamped to their limits), then at most \p iterations damped least-squares
/// steps (Levenberg-Marquardt) over the 6 base coordinates and the 20 joints, joints kept within
/// their limits. The keypoints stand for the joints' origins (CMC, MCP, PIP, DIP, IP), the
/// fingertips and the wrist (the palm's origin) of the model.
/// \throws topograsp::invalid_argument naming "keypoints" if a keypoint is not finite, or
///         "iterations" if it is negative.
template <class = void>
[[nodiscard]] KeypointFit fit_human_hand(const KeypointGrasp& g, int iterations = 200) {
  for (const Vec3& k : g.keypoints)
    if (!k.allFinite()) detail::throw_invalid_argument("keypoints", "a keypoint is not finite");
  if (iterations < 0) detail::throw_invalid_argument("iterations", "expected >= 0");
  constexpr int n = models::human_hand_free.nq;  // the base, then the hand's joints
  const std::array<LinkPoint, keypoint_count> points = detail::human_keypoint_points();
  // The palm's rigid fit: the wrist, the thumb's CMC and the four MCPs at q = 0.
  const Vec<models::human_hand.nq> q0 =
      clamp_to_limits<models::human_hand>(Vec<models::human_hand.nq>::Zero());
  KinematicsData<models::human_hand_free> d;
  forward_kinematics(d, free_configuration<models::human_hand>(Eigen::Isometry3d::Identity(), q0));
  constexpr std::array<std::size_t, 6> palm{0, 1, 5, 9, 13, 17};
  std::array<Vec3, 6> model, target;
  for (std::size_t i = 0; i < palm.size(); ++i) {
    model[i] = world_point(d, points[palm[i]]);
    target[i] = g.keypoints[palm[i]];
  }
  const Eigen::Isometry3d root = detail::rigid_fit(model, target);
  Vec<n> q = free_configuration<models::human_hand>(root, q0);
  const Vec<n> lo = lower_limits<models::human_hand_free>(),
               hi = upper_limits<models::human_hand_free>();
  constexpr int rows = 3 * keypoint_count;
  const auto residual = [&](const Vec<n>& x, Vec<rows>& e) {
    forward_kinematics(d, x);
    for (int i = 0; i < keypoint_count; ++i)
      e.template segment<3>(3 * i) = world_point(d, points[static_cast<std::size_t>(i)]) -
                                     g.keypoints[static_cast<std::size_t>(i)];
    return e.squaredNorm();
  };
  Vec<rows> e;
  double cost = residual(q, e);
  KeypointFit fit;
  Mat<rows, n> J;
  BoundedLeastSquaresOptions lm;
  lm.iterations = iterations;
  lm.settled = 1e-14;
  lm.max_damping = 1e8;
  const BoundedLeastSquaresResult lmr = bounded_least_squares(
      q, e, cost, lo, hi, residual,
      [&](Mat<rows, n>& Jt) {
        for (int i = 0; i < keypoint_count; ++i) {
          const LinkPoint& p = points[static_cast<std::size_t>(i)];
          Jt.template middleRows<3>(3 * i) = point_jacobian(d, p.link, world_point(d, p));
        }
      },
      J, lm);
  fit.iterations = lmr.iterations;
  cost = lmr.cost;
  forward_kinematics(d, q);
  fit.grasp.root =
      link_pose(d, models::human_hand_free.find_link(models::human_hand.links[0].spec.name.view()));
  fit.grasp.q = q.template tail<models::human_hand.nq>();
  fit.error.rms = std::sqrt(cost / keypoint_count);
  for (int i = 0; i < keypoint_count; ++i)
    fit.error.max = std::max(fit.error.max, e.template segment<3>(3 * i).norm());
  return fit;
}

/// The keypoints the human hand model \p grasp places (object frame): what fit_human_hand() fits
/// (a demonstration's keypoints, for a round trip or a file made from a model grasp).
template <class = void>
[[nodiscard]] KeypointGrasp human_keypoints(const HandGrasp<models::human_hand>& grasp,
                                            std::string object) {
  const std::array<LinkPoint, keypoint_count> points = detail::human_keypoint_points();
  KinematicsData<models::human_hand_free> d;
  forward_kinematics(d, free_configuration<models::human_hand>(grasp.root, grasp.q));
  KeypointGrasp g;
  g.object = std::move(object);
  for (std::size_t i = 0; i < points.size(); ++i) g.keypoints[i] = world_point(d, points[i]);
  return g;
}

/// A recorded human grasp \p recorded of \p object as a demonstration (id \p id), judged as
/// demonstrate() judges a planned one: the human hand fitted to its keypoints (fit_human_hand();
/// the fit in \p fit if not null), its joints moved toward the planned demonstrations' open
/// pre-shape (human_preshape) a tenth of the way at a time until the hand is clear of the object
/// (keypoints are taken on a hand that touches it, and a fit may overlap it by millimetres), moved
/// along its palm's approach to contact (place_hand_at_contact, at
/// most options.standoff further), closed with the human hand's holding torques and judged by the
/// stability suite (and the second judge). Its hypothesis is the fitted grasp frame (box and face
/// -1: from no box). Not reached when the hand cannot be placed clear of the object.
/// \throws topograsp::invalid_argument naming "recorded.object" when the recording names another
///         object than \p object, and as fit_human_hand() for keypoints that are not finite.
template <class = void>
[[nodiscard]] HumanGrasp demonstrate_recorded(const GraspObject& object,
                                              const KeypointGrasp& recorded, int id,
                                              const GraspSimOptions& options = {},
                                              KeypointFit* fit = nullptr) {
  if (recorded.object != object.name)
    detail::throw_invalid_argument("recorded.object", "the recording is of \"" + recorded.object +
                                                          "\", not of \"" + object.name + "\"");
  const KeypointFit fitted = fit_human_hand(recorded);
  if (fit != nullptr) *fit = fitted;
  HumanGrasp g;
  g.id = id;
  g.fit_error = fitted.error;
  const Eigen::Isometry3d T = grasp_frame<models::human_hand>(fitted.grasp);
  g.hypothesis.box = g.hypothesis.face = -1;
  g.hypothesis.centre = T.translation();
  g.hypothesis.approach = T.linear().col(2);
  g.hypothesis.up = T.linear().col(0);
  // Opened toward the planned demonstrations' pre-shape, a tenth of the way at a time, until the
  // hand is clear of the object (all the way when the palm touches it: then the approach below
  // backs the hand off and brings it in again, as a planned demonstration comes in).
  const Composite shape = object.composite();
  const Vec<models::human_hand.nq> pre = human_preshape();
  Vec<models::human_hand.nq> opened = fitted.grasp.q;
  KinematicsData<models::human_hand_free> d;
  for (int k = 1; k <= 10; ++k) {
    forward_kinematics(d, free_configuration<models::human_hand>(fitted.grasp.root, opened));
    if (hand_object_distance(d, shape) >= options.contact_gap) break;
    opened = fitted.grasp.q + 0.1 * k * (pre - fitted.grasp.q);
  }
  const Vec3 approach = fitted.grasp.root.linear() * grasp_approach<models::human_hand>(opened);
  const std::optional<Eigen::Isometry3d> placed = place_hand_at_contact<models::human_hand>(
      object, fitted.grasp.root, opened, approach, options, options.standoff);
  if (!placed) return g;
  detail::judge_human_closing(
      object,
      detail::close_human_at(object, free_configuration<models::human_hand>(*placed, opened),
                             options),
      options, g);
  return g;
}

#ifdef TOPOGRASP_EXTERN_HAND_INDEPENDENT
// Compiled once, in the one translation unit that includes grasp/hand_independent.hpp
// (docs/benchmarks.md, "Compiling the transfer once per program").
extern template HumanGrasp demonstrate_recorded<void>(const GraspObject&, const KeypointGrasp&, int,
                                                      const GraspSimOptions&, KeypointFit*);
#endif

}  // namespace topograsp
