// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The shipped robot hands' transfer steps and the hand-independent templates, compiled once for
/// the project's programs and tests: compiled/<hand>.cpp compile each hand's
/// (TOPOGRASP_COMPILE_HAND, grasp/compiled_hand.hpp; object libraries topograsp_compiled_<hand>)
/// and compiled/hand_independent.cpp the rest (object library topograsp_compiled), and every unit
/// that transfers to a shipped hand includes this header, which declares them compiled there
/// (apps/CMakeLists.txt; docs/benchmarks.md, "Compiling the transfer once per program"). The
/// SDH's paper setting (grasp/transfer/sdh.hpp: transfer(), transfer_shuffled()) is compiled
/// with the SDH.
#pragma once

#include <topograsp/grasp/compiled_hand.hpp>
#include <topograsp/grasp/transfer/sdh.hpp>
#include <topograsp/model/models/allegro_hand.hpp>
#include <topograsp/model/models/barrett_bh8.hpp>
#include <topograsp/model/models/leap_hand.hpp>
#include <topograsp/model/models/schunk_sdh.hpp>
#include <topograsp/model/models/shadow_hand.hpp>

TOPOGRASP_EXTERN_HAND(topograsp::models::schunk_sdh);
TOPOGRASP_EXTERN_HAND(topograsp::models::barrett_bh8);
TOPOGRASP_EXTERN_HAND(topograsp::models::allegro_hand);
TOPOGRASP_EXTERN_HAND(topograsp::models::leap_hand);
TOPOGRASP_EXTERN_HAND(topograsp::models::shadow_hand);

// The SDH's paper setting, instantiated as a template with nothing to give (TOPOGRASP_SDH_SETTING
// with kind extern here, empty in compiled/sdh.cpp).
#define TOPOGRASP_SDH_SETTING(kind)                                                              \
  kind template topograsp::SdhTransfer topograsp::transfer<void>(                                \
      topograsp::TransferMethod, const topograsp::GraspObject&, const topograsp::HumanGrasp&,    \
      const topograsp::TransferOptions&);                                                        \
  kind template topograsp::SdhTransfer topograsp::transfer_shuffled<void>(                       \
      const topograsp::GraspObject&, const topograsp::HumanGrasp&, const topograsp::HumanGrasp*, \
      const topograsp::TransferOptions&)

TOPOGRASP_SDH_SETTING(extern);
