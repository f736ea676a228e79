// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The grasp module: objects, box hypotheses, human demonstrations and the transfer methods.
#pragma once

#include <topograsp/grasp/check_hand.hpp>
#include <topograsp/grasp/grasp_identity.hpp>
#include <topograsp/grasp/hand_axes.hpp>
#include <topograsp/grasp/hand_grasp.hpp>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/hypothesis.hpp>
#include <topograsp/grasp/keypoint_fit.hpp>
#include <topograsp/grasp/keypoints.hpp>
#include <topograsp/grasp/mesh_object.hpp>
#include <topograsp/grasp/object.hpp>
#include <topograsp/grasp/placement.hpp>
#include <topograsp/grasp/transfer.hpp>
