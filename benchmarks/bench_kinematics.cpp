// SPDX-License-Identifier: BSD-3-Clause
// Forward kinematics of all frames, and with the fingertip Jacobians, for the 20-DOF human hand,
// the 14-DOF arm + SDH and the hands imported from MJCF (Allegro, LEAP, Shadow); side by side with
// Orocos KDL on the same trees when it is found.
#include <limits>
#include <random>
#include <vector>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/model/models/allegro_hand.hpp>
#include <topograsp/model/models/leap_hand.hpp>
#include <topograsp/model/models/shadow_hand.hpp>

#include "support/random.hpp"
#include "support/ratio_reporter.hpp"

#ifdef TOPOGRASP_HAVE_KDL
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainjnttojacsolver.hpp>
#include <kdl/jacobian.hpp>
#endif

namespace {

using namespace topograsp;

constexpr int k_samples = 64;
constexpr double k_full_limits = std::numeric_limits<double>::infinity();

// Configurations inside the limits, cycled through so nothing can be folded at compile time.
template <const auto& M>
std::vector<Vec<M.nq>> configurations() {
  std::mt19937_64 rng(1);
  std::vector<Vec<M.nq>> qs(k_samples);
  for (auto& q : qs) q = test::random_configuration<M>(rng, k_full_limits);
  return qs;
}

// The tip frame of every finger, in finger order.
template <const auto& M>
std::vector<int> tip_frames() {
  std::vector<int> tips;
  for (const Finger& f : M.fingers)
    tips.push_back(M.find_frame(f.spec.chain[static_cast<std::size_t>(f.size - 1)].view()));
  return tips;
}

template <const auto& M>
void fk_all_frames(benchmark::State& state) {
  const auto qs = configurations<M>();
  KinematicsData<M> d;
  std::size_t i = 0;
  for (auto _ : state) {
    forward_kinematics(d, qs[i++ % k_samples]);
    benchmark::DoNotOptimize(d.frame_p.data());
    benchmark::ClobberMemory();
  }
}

template <const auto& M>
void fk_tip_jacobians(benchmark::State& state) {
  const auto qs = configurations<M>();
  const auto tips = tip_frames<M>();
  KinematicsData<M> d;
  Mat<6, M.nq> J;
  std::size_t i = 0;
  for (auto _ : state) {
    forward_kinematics(d, qs[i++ % k_samples]);
    for (const int f : tips) {
      J = frame_jacobian(d, f);
      benchmark::DoNotOptimize(J.data());
    }
    benchmark::ClobberMemory();
  }
}

#ifdef TOPOGRASP_HAVE_KDL
// One KDL chain per fingertip, from the root to the tip, built from the same model the way URDF
// parsers do (one segment per link: the joint at the link origin, its axis in the parent frame).
// Mimic joints get their own chain entry, set from their source.
template <const auto& M>
struct KdlHand {
  struct FingerChain {
    KDL::Chain chain;
    std::vector<int> q_index;  // configuration entry of each chain joint
    std::vector<double> mult, offset;
    // The chain's joint values from the model's configuration x (mimic joints follow their source).
    template <class X>
    void joints_from(const X& x, KDL::JntArray& q) const {
      for (std::size_t j = 0; j < q_index.size(); ++j)
        q(static_cast<unsigned>(j)) = mult[j] * x[q_index[j]] + offset[j];
    }
  };
  std::vector<FingerChain> fingers;

  KdlHand() {
    for (const int f : tip_frames<M>()) {
      FingerChain c;
      std::vector<int> path;
      for (int l = M.frames[static_cast<std::size_t>(f)].link; l >= 0;
           l = M.links[static_cast<std::size_t>(l)].parent)
        path.insert(path.begin(), l);
      for (const int l : path) {
        const Link& link = M.links[static_cast<std::size_t>(l)];
        const Pose& o = link.spec.origin;
        const KDL::Frame origin(
            KDL::Rotation(o.R[0], o.R[1], o.R[2], o.R[3], o.R[4], o.R[5], o.R[6], o.R[7], o.R[8]),
            KDL::Vector(o.p[0], o.p[1], o.p[2]));
        const KDL::Vector axis = origin.M * KDL::Vector(link.axis[0], link.axis[1], link.axis[2]);
        KDL::Joint joint(link.spec.name.view().data());
        if (link.spec.type == JointType::revolute)
          joint = KDL::Joint(link.spec.name.view().data(), origin.p, axis, KDL::Joint::RotAxis);
        else if (link.spec.type == JointType::prismatic)
          joint = KDL::Joint(link.spec.name.view().data(), origin.p, axis, KDL::Joint::TransAxis);
        c.chain.addSegment(KDL::Segment(link.spec.name.view().data(), joint, origin));
        if (link.spec.type != JointType::fixed) {
          c.q_index.push_back(link.q);
          c.mult.push_back(link.actuated ? 1.0 : link.spec.multiplier);
          c.offset.push_back(link.actuated ? 0.0 : link.spec.offset);
        }
      }
      // The tip frame's offset as a last fixed segment.
      const Pose& t = M.frames[static_cast<std::size_t>(f)].spec.offset;
      c.chain.addSegment(KDL::Segment(
          "tip", KDL::Joint(KDL::Joint::None),
          KDL::Frame(
              KDL::Rotation(t.R[0], t.R[1], t.R[2], t.R[3], t.R[4], t.R[5], t.R[6], t.R[7], t.R[8]),
              KDL::Vector(t.p[0], t.p[1], t.p[2]))));
      fingers.push_back(std::move(c));
    }
  }
};

template <const auto& M>
void kdl_fk_all_frames(benchmark::State& state) {
  const auto qs = configurations<M>();
  KdlHand<M> hand;
  std::vector<KDL::ChainFkSolverPos_recursive> fk;
  std::vector<KDL::JntArray> q;
  std::vector<std::vector<KDL::Frame>> frames;
  for (auto& c : hand.fingers) {
    fk.emplace_back(c.chain);
    q.emplace_back(c.chain.getNrOfJoints());
    frames.emplace_back(c.chain.getNrOfSegments());
  }
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& x = qs[i++ % k_samples];
    for (std::size_t c = 0; c < hand.fingers.size(); ++c) {
      hand.fingers[c].joints_from(x, q[c]);
      fk[c].JntToCart(q[c], frames[c]);
      benchmark::DoNotOptimize(frames[c].data());
    }
    benchmark::ClobberMemory();
  }
}

template <const auto& M>
void kdl_fk_tip_jacobians(benchmark::State& state) {
  const auto qs = configurations<M>();
  KdlHand<M> hand;
  std::vector<KDL::ChainFkSolverPos_recursive> fk;
  std::vector<KDL::ChainJntToJacSolver> jac;
  std::vector<KDL::JntArray> q;
  std::vector<KDL::Jacobian> J;
  for (auto& c : hand.fingers) {
    fk.emplace_back(c.chain);
    jac.emplace_back(c.chain);
    q.emplace_back(c.chain.getNrOfJoints());
    J.emplace_back(c.chain.getNrOfJoints());
  }
  KDL::Frame tip;
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& x = qs[i++ % k_samples];
    for (std::size_t c = 0; c < hand.fingers.size(); ++c) {
      hand.fingers[c].joints_from(x, q[c]);
      fk[c].JntToCart(q[c], tip);
      jac[c].JntToJac(q[c], J[c]);
      benchmark::DoNotOptimize(tip.p.data);
      benchmark::DoNotOptimize(J[c].data.data());
    }
    benchmark::ClobberMemory();
  }
}
#endif

// The same check KDL's side needs: both implementations compute the same fingertips.
template <const auto& M>
void register_all(const char* name) {
  const std::string n(name);
  benchmark::RegisterBenchmark(("fk_all_frames/" + n + "/topograsp").c_str(), fk_all_frames<M>);
  benchmark::RegisterBenchmark(("fk_tip_jacobians/" + n + "/topograsp").c_str(),
                               fk_tip_jacobians<M>);
#ifdef TOPOGRASP_HAVE_KDL
  benchmark::RegisterBenchmark(("fk_all_frames/" + n + "/kdl").c_str(), kdl_fk_all_frames<M>);
  benchmark::RegisterBenchmark(("fk_tip_jacobians/" + n + "/kdl").c_str(), kdl_fk_tip_jacobians<M>);
#endif
}

}  // namespace

int main(int argc, char** argv) {
  register_all<models::human_hand>("human_hand_20dof");
  register_all<models::schunk_arm_sdh>("schunk_arm_sdh_14dof");
  register_all<models::human_hand_free>("human_hand_free_26dof");
  register_all<models::allegro_hand>("allegro_hand_16dof");
  register_all<models::leap_hand>("leap_hand_16dof");
  register_all<models::shadow_hand>("shadow_hand_22dof");
  return topograsp::bench::run_with_ratios(argc, argv);
}
