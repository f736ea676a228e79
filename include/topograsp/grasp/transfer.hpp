// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The transfer methods, one header each under grasp/transfer/: a grasp of one hand moved to
/// another by topological synergies (the paper: AICO toward the source's windings), by the paper's
/// baseline "transplant", by fingertip mapping (Rohling and Hollerbach 1993) and by a
/// virtual-finger mapping (Arbib, Iberall and Lyons 1985); each result is placed at contact,
/// closed and judged by the stability suite. transfer_hand() and transfer_hand_on_arm() dispatch
/// for any pair of hands; the functions of the paper's Table I (transfer_topological, transfer()
/// and the baselines on the SDH) are thin calls of the same methods.
/// docs/architecture.md, "Adding a transfer method", says how a method is added.
#pragma once

#include <topograsp/grasp/transfer/common.hpp>
#include <topograsp/grasp/transfer/fingertip.hpp>
#include <topograsp/grasp/transfer/hand.hpp>
#include <topograsp/grasp/transfer/options.hpp>
#include <topograsp/grasp/transfer/sdh.hpp>
#include <topograsp/grasp/transfer/topological.hpp>
#include <topograsp/grasp/transfer/transplant.hpp>
#include <topograsp/grasp/transfer/virtual_finger.hpp>
