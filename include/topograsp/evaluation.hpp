// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The evaluation module: the protocols that judge a grasp in the physics module's stepper. A hand
/// scene (a hand model's links as kinematic bodies holding an object), closing the hand on the
/// object, the stability suite (the paper's shake, the six gravity directions, the hard shake)
/// that runs on any GraspScene, the contact wrenches of a grasp (its Ferrari-Canny epsilon is
/// in evaluation/grasp_quality.hpp, which needs qhull), and the statistics of success rates and
/// paired comparisons. See docs/evaluation.md.
#pragma once

#include <topograsp/evaluation/close_hand.hpp>
#include <topograsp/evaluation/grasp_scene.hpp>
#include <topograsp/evaluation/grasp_wrench.hpp>
#include <topograsp/evaluation/hand_scene.hpp>
#include <topograsp/evaluation/hold_balance.hpp>
#include <topograsp/evaluation/stability_suite.hpp>
#include <topograsp/evaluation/statistics.hpp>
