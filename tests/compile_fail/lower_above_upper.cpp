// expect: lower limit above upper limit
// SPDX-License-Identifier: BSD-3-Clause
// A malformed model must not compile, and the diagnostic must say why.
#include <topograsp/model/model.hpp>

using namespace topograsp;

#ifdef TOPOGRASP_SHOULD_FAIL_TO_BUILD
inline constexpr auto model = make_model(
    "m", links(root("base"), revolute("a", "base", {}, {0, 1, 0}, 1.0, -1.0)), shapes(), frames());
#else
inline constexpr auto model = make_model(
    "m", links(root("base"), revolute("a", "base", {}, {0, 1, 0}, -1.0, 1.0)), shapes(), frames());
#endif

int main() { return model.nq > 100 ? 1 : 0; }
