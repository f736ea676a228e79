// expect: effort, velocity and armature must be in
// SPDX-License-Identifier: BSD-3-Clause
// A joint whose actuator has a negative torque limit must not compile.
#include <topograsp/model/model.hpp>

using namespace topograsp;

#ifdef TOPOGRASP_SHOULD_FAIL_TO_BUILD
inline constexpr double effort = -1.0;
#else
inline constexpr double effort = 1.0;
#endif

inline constexpr auto model = make_model(
    "m",
    links(root("base"), revolute("a", "base", {}, {0, 1, 0}, -1, 1).actuator(effort, 1.0, 1e-4)),
    shapes(), frames());

int main() { return model.links[1].spec.effort > 0.0 ? 0 : 1; }
