// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The physics module: the rigid-body stepper (World), its bodies, shapes and contacts. Judging a
/// grasp with it (hand scenes, closing a hand, the shake test) is the evaluation module,
/// <topograsp/evaluation.hpp>. See docs/stepper.md.
#pragma once

#include <topograsp/physics/contact.hpp>
#include <topograsp/physics/contact_set.hpp>
#include <topograsp/physics/contact_solver.hpp>
#include <topograsp/physics/narrow_phase.hpp>
#include <topograsp/physics/polytope.hpp>
#include <topograsp/physics/rigid_body.hpp>
#include <topograsp/physics/stepper_options.hpp>
#include <topograsp/physics/world.hpp>
