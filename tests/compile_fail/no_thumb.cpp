// expect: a hand needs a thumb
// SPDX-License-Identifier: BSD-3-Clause
// A malformed model must not compile, and the diagnostic must say why.
#include <topograsp/model/model.hpp>

using namespace topograsp;

#ifdef TOPOGRASP_SHOULD_FAIL_TO_BUILD
inline constexpr auto model =
    make_model("m",
               links(root("palm"), revolute("f1", "palm", {}, {0, 1, 0}, -1, 1),
                     revolute("f2", "palm", {}, {0, 1, 0}, -1, 1)),
               shapes(), frames(), hand("palm", finger("one", {"f1"}), finger("two", {"f2"})));
#else
inline constexpr auto model =
    make_model("m",
               links(root("palm"), revolute("f1", "palm", {}, {0, 1, 0}, -1, 1),
                     revolute("f2", "palm", {}, {0, 1, 0}, -1, 1)),
               shapes(), frames(), hand("palm", finger("one", {"f1"}), thumb("two", {"f2"})));
#endif

int main() { return model.nq > 100 ? 1 : 0; }
