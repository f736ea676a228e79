// SPDX-License-Identifier: BSD-3-Clause
// Compile-time tests: this file passes if it compiles.
#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>

namespace {
using namespace topograsp;

static_assert(KinematicModel<decltype(models::schunk_sdh)>);
static_assert(HandModel<decltype(models::schunk_sdh)>);
static_assert(HandModel<decltype(models::schunk_arm_sdh)>);
static_assert(KinematicModel<decltype(models::schunk_arm)>);
static_assert(!HandModel<decltype(models::schunk_arm)>);
static_assert(!KinematicModel<int>);
static_assert(!KinematicModel<LinkSpec>);

static_assert(EigenDense<Vec3>);
static_assert(EigenDense<decltype(Vec<6>().head<3>())>);
static_assert(EigenDense<Eigen::Map<const Vec3>>);
static_assert(!EigenDense<double>);
static_assert(!EigenDense<Eigen::Array3d>);

// A model is a structural type: usable by value as a template argument.
template <auto M>
struct ByValue {
  static constexpr int nq = M.nq;
};
static_assert(ByValue<models::schunk_sdh>::nq == 7);

// Sizes known at compile time become fixed Eigen sizes.
static_assert(KinematicsData<models::schunk_arm_sdh>::nq == 14);
static_assert(decltype(frame_jacobian(std::declval<const KinematicsData<models::human_hand>&>(),
                                      0))::ColsAtCompileTime == 20);

// A user-written model compiles to the expected sizes.
inline constexpr auto two_link =
    make_model("two_link",
               links(root("base"), revolute("j1", "base", at(0, 0, 0.1), {0, 0, 1}, -1, 1),
                     prismatic("j2", "j1", at(0.2, 0, 0), {1, 0, 0}, 0, 0.1)),
               shapes(sphere("j2", {0, 0, 0}, 0.01)), frames(frame("tool", "j2", at(0.05, 0, 0))));
static_assert(two_link.nq == 2 && two_link.frame("tool") == 0 && two_link.link("j2") == 2);
static_assert(!two_link.is_hand());
}  // namespace
