// SPDX-License-Identifier: BSD-3-Clause
// Prints the fingertip positions of every shipped hand, open and closed, and of the SDH on the
// arm: the first thing to look at when checking a model.
#include <cstdio>

#include <topograsp/topograsp.hpp>

namespace {

using namespace topograsp;

// Prints every frame of model M at configuration q, plus the fingertip of each finger.
template <const auto& M>
void print_model(const char* label, const Vec<M.nq>& q) {
  KinematicsData<M> d;
  forward_kinematics(d, q);
  std::printf("%s (%s, %d DOF)\n", M.name.view().data(), label, M.nq);
  for (const Finger& f : M.fingers) {
    const Vec3 tip = world_point(d, f.points[static_cast<std::size_t>(f.size - 1)]);
    std::printf("  %-10s tip  % .4f % .4f % .4f m%s\n", f.spec.name.view().data(), tip.x(), tip.y(),
                tip.z(), f.spec.thumb ? "  (thumb)" : "");
  }
}

// Every joint at the fraction s of the way from its lower limit to its upper limit in its closing
// direction, other joints at 0 (or the middle of their range when 0 is outside it).
template <const auto& M>
Vec<M.nq> preshape(double s) {
  Vec<M.nq> q;
  for (int i = 0; i < M.nq; ++i) {
    const LinkSpec& j = M.joint_spec(i);
    const double rest = j.lower <= 0.0 && 0.0 <= j.upper ? 0.0 : 0.5 * (j.lower + j.upper);
    q[i] = j.closing > 0   ? rest + s * (j.upper - rest)
           : j.closing < 0 ? rest + s * (j.lower - rest)
                           : rest;
  }
  return q;
}

}  // namespace

int main() {
  print_model<models::schunk_sdh>("home", preshape<models::schunk_sdh>(0.0));
  print_model<models::schunk_sdh>("half closed", preshape<models::schunk_sdh>(0.5));
  print_model<models::human_hand>("open", preshape<models::human_hand>(0.0));
  print_model<models::human_hand>("half closed", preshape<models::human_hand>(0.5));
  print_model<models::barrett_bh8>("open", preshape<models::barrett_bh8>(0.0));
  print_model<models::barrett_bh8>("half closed", preshape<models::barrett_bh8>(0.5));
  print_model<models::schunk_arm_sdh>("arm at zero, hand home",
                                      preshape<models::schunk_arm_sdh>(0.0));
  return 0;
}
