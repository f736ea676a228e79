// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The task module: the TaskVariable and TaskStack concepts, winding numbers of hand curves, the
/// collision potential, pose, limit and posture tasks, linking numbers and writhe, and TaskSet
/// with its schedules.
#pragma once

#include <topograsp/task/axis_task.hpp>
#include <topograsp/task/collision_task.hpp>
#include <topograsp/task/concepts.hpp>
#include <topograsp/task/hand_curve.hpp>
#include <topograsp/task/joint_limit_task.hpp>
#include <topograsp/task/line_task.hpp>
#include <topograsp/task/linking.hpp>
#include <topograsp/task/orientation_task.hpp>
#include <topograsp/task/position_task.hpp>
#include <topograsp/task/posture_task.hpp>
#include <topograsp/task/schedule.hpp>
#include <topograsp/task/task_set.hpp>
#include <topograsp/task/winding.hpp>
#include <topograsp/task/winding_descriptor.hpp>
#include <topograsp/task/winding_task.hpp>
#include <topograsp/task/writhe_task.hpp>
