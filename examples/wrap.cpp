// SPDX-License-Identifier: BSD-3-Clause
// The SDH on the 7-DOF Schunk arm moves from its home pose to wrap two of its hand curves around a
// cylinder to given winding values while avoiding collision (paper Fig. 4 and Fig. 7), planned
// with AICO in dynamic mode. Prints the sweeps, writes the windings over time as CSV and SVG.
//
//   wrap [--out DIR] [--steps T] [--mode direct|coupled] [--goal W1,W2]
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <topograsp/aico.hpp>
#include <topograsp/geometry/composite.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/render/svg_plot.hpp>
#include <topograsp/task/collision_task.hpp>
#include <topograsp/task/joint_limit_task.hpp>
#include <topograsp/task/posture_task.hpp>
#include <topograsp/task/task_set.hpp>
#include <topograsp/task/winding_task.hpp>

namespace {

using namespace topograsp;
constexpr const auto& robot = models::schunk_arm_sdh;
constexpr int nq = robot.nq;

int usage(const char* argv0, int status) {
  std::fprintf(status == 0 ? stdout : stderr,
               "usage: %s [--out DIR] [--steps T] [--mode direct|coupled] [--goal W1,W2]\n"
               "Plans the SDH on the Schunk arm wrapping two curves around a cylinder.\n",
               argv0);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = "wrap-out";
  AicoOptions options;
  options.steps = 40;
  options.control_precision = 1e-2;
  options.max_sweeps = 100;
  TopologicalOptions topology;
  Vec2 goal(0.8, 0.8);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if (a == "--help" || a == "-h") return usage(argv[0], 0);
    if (a == "--out" && has_value) {
      out = argv[++i];
    } else if (a == "--steps" && has_value) {
      options.steps = std::atoi(argv[++i]);
    } else if (a == "--mode" && has_value) {
      const std::string m = argv[++i];
      if (m != "direct" && m != "coupled") return usage(argv[0], 2);
      topology.mode = m == "direct" ? TopologicalMode::direct : TopologicalMode::coupled;
    } else if (a == "--goal" && has_value) {
      if (std::sscanf(argv[++i], "%lf,%lf", &goal[0], &goal[1]) != 2) return usage(argv[0], 2);
    } else {
      return usage(argv[0], 2);
    }
  }

  // The scene: the arm's home pose bent a little; a cylinder (radius 2 cm, 20 cm long) 10 cm in
  // front of the palm at a reachable pose, its axis across the fingers' flexion plane. The
  // windings are taken around the cylinder's centre.
  Vec<nq> home = Vec<nq>::Zero();
  home[1] = 0.2;
  home[3] = 0.3;
  home[5] = 0.2;
  KinematicsData<robot> d;
  Vec<nq> reach = Vec<nq>::Zero();
  reach[1] = 0.5;
  reach[3] = 0.8;
  reach[5] = 0.5;
  forward_kinematics(d, reach);
  const auto palm = static_cast<std::size_t>(robot.frame("palm_centre"));
  const Mat3 R = d.frame_R[palm];
  const Vec3 centre = d.frame_p[palm] + 0.10 * R.col(2);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = centre;
  pose.linear() << R.col(0), R.col(1).cross(R.col(0)), R.col(1);
  const Composite cylinder({Primitive::cylinder(pose, 0.02, 0.1)});
  // The other tasks: collision with the cylinder (target 0), a penalty beyond the joint limits
  // and a weak pull toward the home posture, each with a constant precision.
  const CollisionTask<robot> collision(cylinder, 0.02);
  const auto base = make_task_set(
      scheduled(collision, constant_target(Vec<1>(0.0)), constant_precision(1e3)),
      scheduled(JointLimitTask<robot>(), constant_target(Vec<nq>(Vec<nq>::Zero())),
                constant_precision(1e4)),
      scheduled(PostureTask<robot>(), constant_target(home), constant_precision(1e-2)));
  const WindingTask<robot, 2> windings({0, 1}, centre);

  try {
    const auto r = solve_topological<robot>(base, windings, goal, home, options, topology);
    std::printf("AICO, dynamic mode, T = %d, %s topological targets, goal windings (%.3f, %.3f)\n",
                options.steps, to_string(topology.mode).data(), goal[0], goal[1]);
    std::printf("%6s %14s %12s %10s %9s\n", "sweep", "cost", "damping", "time (ms)", "accepted");
    for (std::size_t k = 0; k < r.aico.sweep_log.size(); ++k) {
      const AicoSweepRecord& s = r.aico.sweep_log[k];
      std::printf("%6zu %14.6g %12.4g %10.3f %9s\n", k + 1, s.cost, s.damping, 1e3 * s.seconds,
                  s.accepted ? "yes" : "no");
    }
    forward_kinematics(d, r.final_configuration());
    const Vec2 w = r.final_value();
    std::printf(
        "%s (%s) after %d sweeps, %d rounds; final windings (%.4f, %.4f); "
        "closest distance to the cylinder %.4f m\n",
        to_string(r.aico.status).data(), to_string(r.aico.termination).data(), r.aico.sweeps,
        r.rounds, w[0], w[1], collision.min_distance(d));

    std::filesystem::create_directories(out);
    std::ofstream csv(out + "/windings.csv");
    csv << "t,time_s,w1,w2,target1,target2\n";
    std::vector<double> t(r.values.size()), w1(t.size()), w2(t.size()), y1(t.size()), y2(t.size());
    const double tau = options.duration / options.steps;
    for (std::size_t u = 0; u < t.size(); ++u) {
      t[u] = static_cast<double>(u);
      w1[u] = r.values[u][0];
      w2[u] = r.values[u][1];
      y1[u] = r.targets[u][0];
      y2[u] = r.targets[u][1];
      csv << u << ',' << tau * t[u] << ',' << w1[u] << ',' << w2[u] << ',' << y1[u] << ',' << y2[u]
          << '\n';
    }
    SvgLinePlot plot("Windings of the SDH's two curves around the cylinder", "step t", "winding w");
    plot.add_series("w(gamma_1)", t, w1);
    plot.add_series("w(gamma_2)", t, w2);
    plot.add_series("target y_1", t, y1);
    plot.add_series("target y_2", t, y2);
    plot.write(out + "/windings.svg");
    std::printf("wrote %s/windings.csv and %s/windings.svg\n", out.c_str(), out.c_str());
    const bool reached = (w - goal).lpNorm<Eigen::Infinity>() < 0.05;
    return reached && r.aico.status != Status::numerical_issue ? 0 : 1;
  } catch (const topograsp::invalid_argument& e) {
    std::fprintf(stderr, "wrap: %s\n", e.what());
    return 2;
  }
}
