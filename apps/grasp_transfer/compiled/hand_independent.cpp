// SPDX-License-Identifier: BSD-3-Clause
// The hand-independent templates (grasp/hand_independent.hpp: the human hand's demonstrations, the
// arm's reach, the grasp quality), compiled once for the programs and the tests
// (shipped_hands.hpp).
#include <topograsp/grasp/hand_independent.hpp>
