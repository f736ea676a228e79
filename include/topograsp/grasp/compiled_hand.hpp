// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// What a transfer compiles per target hand, compiled once per program. Every method on a free
/// base (transfer_hand(), from any source: SourceGrasp), its last steps (placing the hand at
/// contact, opening it until clear, closing it and judging the grasp: simulate_hand_grasp), the
/// topological method's planner on the hand's free base (AICO) and the hand's self-check
/// (check_hand(), which closes the hand as the methods do) are templates on the target hand,
/// compiled in every translation unit that transfers to it. A program of several
/// such units writes TOPOGRASP_EXTERN_HAND(model) where all of them see it (a header they include,
/// after this one) and TOPOGRASP_COMPILE_HAND(model) in exactly one, which compiles them; the
/// planner on the arm (transfer_hand_on_arm) stays in each unit that calls it. Both macros go at
/// global scope; model is a hand model's constant (topograsp::models::allegro_hand, a model
/// imported by topograsp_import_hand). grasp/hand_independent.hpp does the same for the
/// hand-independent templates (docs/benchmarks.md, "Compiling the transfer once per program").
#pragma once

#include <optional>

#include <topograsp/grasp/check_hand.hpp>
#include <topograsp/grasp/hand_grasp.hpp>
#include <topograsp/grasp/transfer/hand.hpp>
#include <topograsp/grasp/transfer/topological.hpp>

// The explicit instantiations of TOPOGRASP_EXTERN_HAND (kind extern) and TOPOGRASP_COMPILE_HAND
// (kind empty) for hand model M.
#define TOPOGRASP_HAND_INSTANTIATIONS_(kind, M)                                                \
  kind template void topograsp::simulate_hand_grasp<M>(                                        \
      const topograsp::GraspObject&, const Eigen::Isometry3d&, const topograsp::Vec<M.nq>&,    \
      const topograsp::GraspSimOptions&, const topograsp::SecondJudge<M>&,                     \
      topograsp::HandTransfer<M>&);                                                            \
  kind template std::optional<Eigen::Isometry3d> topograsp::place_hand_at_contact<M>(          \
      const topograsp::GraspObject&, const Eigen::Isometry3d&, const topograsp::Vec<M.nq>&,    \
      const topograsp::Vec3&, const topograsp::GraspSimOptions&, double);                      \
  kind template topograsp::Vec<M.nq> topograsp::open_hand_until_clear<M>(                      \
      const topograsp::GraspObject&, const Eigen::Isometry3d&, topograsp::Vec<M.nq>,           \
      const topograsp::GraspSimOptions&);                                                      \
  kind template topograsp::HandTransfer<M> topograsp::detail::topological_free<M>(             \
      const topograsp::GraspObject&, const Eigen::Isometry3d&,                                 \
      const topograsp::Vec<topograsp::hand_curve_count<M>>&, const topograsp::Vec3&,           \
      const topograsp::TransferOptions&, const topograsp::SecondJudge<M>&,                     \
      topograsp::detail::TransferRun<M>&);                                                     \
  kind template topograsp::HandTransfer<M> topograsp::transfer_hand<M>(                        \
      topograsp::TransferMethod, const topograsp::GraspObject&, const topograsp::SourceGrasp&, \
      const topograsp::TransferOptions&, const topograsp::SecondJudge<M>&);                    \
  kind template topograsp::HandCheck topograsp::check_hand<M>(const topograsp::HandCheckOptions&)

/// Declares hand \p model's transfer steps compiled elsewhere (in the unit with
/// TOPOGRASP_COMPILE_HAND(model)).
#define TOPOGRASP_EXTERN_HAND(model) TOPOGRASP_HAND_INSTANTIATIONS_(extern, model)

/// Compiles hand \p model's transfer steps: in exactly one translation unit of the program.
#define TOPOGRASP_COMPILE_HAND(model) TOPOGRASP_HAND_INSTANTIATIONS_(, model)
