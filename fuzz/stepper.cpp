// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the stepper, World of physics/world.hpp, in double or float.
//
// A world with fuzzed options and up to 4 bodies (fixed, kinematic or dynamic; 1 or 2 shapes;
// sizes, poses, masses, densities, velocities mostly in a working range, sometimes anywhere from
// 1e-300 to 1e300), then up to 16 steps with fuzzed kinematic targets. Anything World refuses with
// topograsp::invalid_argument (options, bodies, velocities, targets) is skipped: that is its
// documented answer. Checked: whenever the status is success - after building and after every
// step - every body's state (position, orientation, velocities, mass, inertia, kinetic energy) and
// every contact point in use is finite. World also promises that a step that fails leaves every
// number finite: checked too.

#include <cmath>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/physics/world.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::BodyType;
using topograsp::ShapeType;
using namespace topograsp::fuzz;

// A positive value: usually in [lo, hi], one time in 8 anything from 1e-300 to 1e300.
double value(FuzzInput& in, double lo, double hi) {
  return in.integer(0, 7) == 0 ? in.magnitude(-300, 300) : in.real(lo, hi);
}

topograsp::Pose pose(FuzzInput& in, double reach) {
  const Eigen::Matrix3d R = in.rotation();
  topograsp::Pose p;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) p.R[static_cast<std::size_t>(3 * r + c)] = R(r, c);
  const bool far = in.integer(0, 15) == 0;
  for (double& x : p.p)
    x = far ? in.real(-1.0, 1.0) * in.magnitude(0, 300) : in.real(-reach, reach);
  return p;
}

std::string pose_str(const topograsp::Pose& p) {
  return "p " + vec_str(p.translation()) + ", R " + mat_str(p.rotation());
}

template <class S>
std::string state_problem(const topograsp::World<S>& world) {
  for (int i = 0; i < world.body_count(); ++i) {
    const topograsp::RigidBody<S>& b = world.body(i);
    const std::string at = "body " + std::to_string(i) + ": ";
    if (!b.x.allFinite()) return at + "position " + vec_str(b.x.template cast<double>());
    if (!b.q.coeffs().allFinite() || !b.R.allFinite()) return at + "orientation not finite";
    if (!b.v.allFinite()) return at + "velocity " + vec_str(b.v.template cast<double>());
    if (!b.w.allFinite()) return at + "angular velocity " + vec_str(b.w.template cast<double>());
    if (!std::isfinite(b.mass) || !std::isfinite(b.inv_mass))
      return at + "mass " + num(static_cast<double>(b.mass)) + ", inverse " +
             num(static_cast<double>(b.inv_mass));
    if (!b.inertia.allFinite() || !b.inv_inertia.allFinite() || !b.inv_inertia_local.allFinite())
      return at + "inertia " + mat_str(b.inertia.template cast<double>()) + ", inverse " +
             mat_str(b.inv_inertia_local.template cast<double>());
    if (!std::isfinite(b.kinetic_energy()))
      return at + "kinetic energy " + num(static_cast<double>(b.kinetic_energy()));
  }
  for (const topograsp::Manifold<S>& m : world.manifolds())
    for (int k = 0; k < m.count; ++k) {
      const topograsp::ContactPoint<S>& c = m.points[static_cast<std::size_t>(k)];
      if (!c.point.allFinite() || !c.normal.allFinite() || !std::isfinite(c.separation) ||
          !std::isfinite(c.step_impulse))
        return "contact between bodies " + std::to_string(m.body_a) + " and " +
               std::to_string(m.body_b) + ": point " + vec_str(c.point.template cast<double>()) +
               ", normal " + vec_str(c.normal.template cast<double>()) + ", separation " +
               num(static_cast<double>(c.separation)) + ", impulse " +
               num(static_cast<double>(c.step_impulse));
    }
  if (!std::isfinite(world.kinetic_energy()))
    return "total kinetic energy " + num(static_cast<double>(world.kinetic_energy()));
  return {};
}

template <class S>
void run(FuzzInput& in, std::string& log) {
  topograsp::StepperOptions o;
  o.time_step = in.flag() ? in.real(1e-4, 0.05) : value(in, 1e-4, 2.0);
  o.substeps = in.integer(1, 8);
  for (double& g : o.gravity) g = in.real(-20.0, 20.0);
  o.speculative_distance = in.real(0.0, 0.01);
  o.linear_damping = in.flag() ? 0.0 : in.real(0.0, 10.0);
  o.angular_damping = in.flag() ? 0.0 : in.real(0.0, 10.0);
  log += "World<" + std::string(sizeof(S) == 4 ? "float" : "double") + ">, time step " +
         num(o.time_step) + ", substeps " + std::to_string(o.substeps) + ", gravity " +
         vec_str(Eigen::Vector3d(o.gravity[0], o.gravity[1], o.gravity[2])) + ", speculative " +
         num(o.speculative_distance) + ", damping " + num(o.linear_damping) + " " +
         num(o.angular_damping) + "\n";
  // The options are in range by construction, but World may refuse combinations it cannot step
  // (e.g. a time step whose fall under gravity exceeds the speculative distance): its documented
  // topograsp::invalid_argument ends the input.
  std::optional<topograsp::World<S>> made;
  try {
    made.emplace(o);
  } catch (const topograsp::invalid_argument& e) {
    return;
  }
  topograsp::World<S>& world = *made;

  const int n_bodies = in.integer(1, 4);
  std::vector<int> kinematic;
  for (int i = 0; i < n_bodies; ++i) {
    std::vector<topograsp::ShapeSpec> shapes(static_cast<std::size_t>(in.integer(1, 2)));
    std::string shapes_log;
    for (topograsp::ShapeSpec& s : shapes) {
      s.type =
          in.pick({ShapeType::sphere, ShapeType::capsule, ShapeType::box, ShapeType::cylinder});
      s.pose = pose(in, 0.2);
      for (double& x : s.size) x = value(in, 0.005, 0.5);
      shapes_log += std::string("    shape type ") + std::to_string(static_cast<int>(s.type)) +
                    ", size " + vec_str(Eigen::Vector3d(s.size[0], s.size[1], s.size[2])) + ", " +
                    pose_str(s.pose) + "\n";
    }
    topograsp::BodyDesc desc;
    desc.type = in.pick({BodyType::fixed, BodyType::kinematic, BodyType::dynamic});
    desc.pose = pose(in, 1.0);
    desc.shapes = shapes;
    desc.mass = in.flag() ? 0.0 : value(in, 0.01, 10.0);
    desc.density = in.flag() ? 1000.0 : value(in, 10.0, 1e4);
    desc.friction = in.real(0.0, 1.5);
    const Eigen::Vector3d v =
        in.vec(-5.0, 5.0) * (in.integer(0, 15) == 0 ? in.magnitude(0, 308) : 1.0);
    const Eigen::Vector3d w = in.vec(-10.0, 10.0);
    log += "body " + std::to_string(i) + ": type " + std::to_string(static_cast<int>(desc.type)) +
           ", " + pose_str(desc.pose) + ", mass " + num(desc.mass) + ", density " +
           num(desc.density) + ", friction " + num(desc.friction) + ", velocity " + vec_str(v) +
           ", angular " + vec_str(w) + "\n" + shapes_log;
    try {
      const int index = world.add_body(desc);
      world.set_velocity(index, v, w);
      if (desc.type == BodyType::kinematic) kinematic.push_back(index);
    } catch (const topograsp::invalid_argument& e) {
      log += std::string("    refused: ") + e.what() + "\n";
    }
  }
  if (const std::string problem = state_problem(world); !problem.empty())
    fuzz_fail("stepper", "after building, status success and " + problem, log);

  const int steps = in.integer(1, 16);
  for (int k = 0; k < steps; ++k) {
    for (const int body : kinematic)
      if (in.flag()) {
        const topograsp::Pose target = pose(in, 1.0);
        log += "step " + std::to_string(k) + ": target of body " + std::to_string(body) + ": " +
               pose_str(target) + "\n";
        try {
          world.set_target(body, target.isometry());
        } catch (const topograsp::invalid_argument& e) {
          log += std::string("    refused: ") + e.what() + "\n";  // documented
        }
      }
    const topograsp::Status status = world.step();
    if (const std::string problem = state_problem(world); !problem.empty())
      fuzz_fail("stepper",
                "after step " + std::to_string(k) + ", status " +
                    std::string(topograsp::to_string(status)) + " and " + problem,
                log);
    if (status != topograsp::Status::success) return;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    FuzzInput in(data, size);
    std::string log;
    try {
      if (in.flag())
        run<float>(in, log);
      else
        run<double>(in, log);
    } catch (const std::exception& e) {
      // World's options and targets are valid by construction, and add_body's refusals are caught:
      // nothing may be thrown here.
      fuzz_fail("stepper", std::string("threw ") + typeid(e).name() + ": " + e.what(), log);
    }
  });
}
