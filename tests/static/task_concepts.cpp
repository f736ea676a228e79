// SPDX-License-Identifier: BSD-3-Clause
// The task models satisfy TaskVariable, TaskSet satisfies TaskStack; other types do not.
#include <topograsp/model/models.hpp>
#include <topograsp/task.hpp>

namespace {

using namespace topograsp;
constexpr auto& k_sdh = models::schunk_sdh;
constexpr auto& k_robot = models::schunk_arm_sdh;

static_assert(TaskVariable<WindingTask<k_sdh>>);
static_assert(TaskVariable<WindingTask<models::human_hand, 2>>);
static_assert(TaskVariable<CollisionTask<k_robot>>);
static_assert(TaskVariable<PositionTask<models::schunk_arm>>);
static_assert(TaskVariable<AxisTask<k_robot>>);
static_assert(TaskVariable<OrientationTask<k_robot>>);
static_assert(TaskVariable<JointLimitTask<k_robot>>);
static_assert(TaskVariable<PostureTask<k_robot>>);
static_assert(TaskVariable<WritheTask<k_sdh, 7, 3>>);
static_assert(WindingTask<k_sdh>::dim == 2 && WindingTask<models::human_hand>::dim == 4);
static_assert(WritheTask<k_sdh, 7, 3>::dim == 12);

using Set = TaskSet<WindingTask<k_robot>, CollisionTask<k_robot>, AxisTask<k_robot>>;
static_assert(TaskStack<Set>);
static_assert(Set::dim == 6 && Set::nq == 14 && Set::size == 3);

static_assert(!TaskVariable<int>);
static_assert(!TaskVariable<Scheduled<PostureTask<k_sdh>>>);
static_assert(!TaskStack<WindingTask<k_sdh>>);
static_assert(!TaskStack<Primitive>);

// Hand curves are computed at compile time for any hand.
static_assert(hand_curve_count<models::barrett_bh8> == 2);
static_assert(hand_curve_chain<models::human_hand, 3>().size() == 9);

}  // namespace
