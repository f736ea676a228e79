// expect: a mimic joint has no actuator of its own
// SPDX-License-Identifier: BSD-3-Clause
// A mimic joint is driven through its source: an actuator of its own must not compile.
#include <topograsp/model/model.hpp>

using namespace topograsp;

#ifdef TOPOGRASP_SHOULD_FAIL_TO_BUILD
inline constexpr auto model = make_model(
    "m",
    links(root("base"), revolute("a", "base", {}, {0, 1, 0}, -1, 1).actuator(1.0, 1.0, 1e-4),
          revolute("b", "base", {}, {0, 1, 0}, -1, 1).mimics("a").actuator(1.0, 1.0)),
    shapes(), frames());
#else
inline constexpr auto model = make_model(
    "m",
    links(root("base"), revolute("a", "base", {}, {0, 1, 0}, -1, 1).actuator(1.0, 1.0, 1e-4),
          revolute("b", "base", {}, {0, 1, 0}, -1, 1).mimics("a")),
    shapes(), frames());
#endif

int main() { return model.nq == 1 ? 0 : 1; }
