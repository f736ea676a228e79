// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The transfer methods by name (TransferMethod) and the point their windings are taken around
/// (WindingReference).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include <topograsp/core/error.hpp>

namespace topograsp {
/// The point the windings of the topological transfer are taken around, for the human's
/// descriptor and the SDH's targets alike.
enum class WindingReference : std::uint8_t {
  centre_of_mass,  ///< the object's centre of mass (the paper)
  nearest_point,   ///< the point of the object nearest the human's grasp centre
};

/// The name of \p r ("centre_of_mass", "nearest_point").
[[nodiscard]] constexpr std::string_view to_string(WindingReference r) noexcept {
  switch (r) {
    case WindingReference::centre_of_mass:
      return "centre_of_mass";
    case WindingReference::nearest_point:
      return "nearest_point";
  }
  return "unknown";
}

/// The reference called \p name ("centre_of_mass" or "nearest_point").
/// \throws topograsp::invalid_argument naming "winding_reference" for any other name.
[[nodiscard]] inline WindingReference winding_reference(std::string_view name) {
  return enum_from_name(name, {WindingReference::centre_of_mass, WindingReference::nearest_point},
                        "winding_reference", "reference");
}

/// The transfer methods.
///
/// The topological method has named variants, so that the paper's method and each of our additions
/// to it are rows of one table (docs/results.md); each is `transfer_topological` with some of
/// TransferOptions set (transfer_method_options), on top of the options given:
/// - topological: topograsp's method as shipped: the paper's tasks (the two largest windings
///   around the centre of mass, the approach axis, collision), plus the SDH's grasp centre on the
///   human's approach line (the line task) and the final approach until contact;
/// - paper: the paper's method as the paper states it: no line task, no final approach;
/// - paper_line: the paper's method plus the line task only;
/// - paper_approach: the paper's method plus the final approach until contact only;
/// - no_windings: topograsp's method without the winding targets (the same plan otherwise);
/// - nearest_point: topograsp's method with the windings taken around the object's point nearest
///   the human's grasp centre;
/// - closed_windings: topograsp's method with the winding targets corrected for the closing
///   (TransferOptions::closing_corrections = 2), so that the windings after the fingers close,
///   not before, are the human's;
/// - no_plan (a control): no plan at all, the hand judged at the plan's start (moved on until
///   contact and closed as every variant is; TransferOptions::plan false);
/// - shuffled_windings (a control): topograsp's method aimed at another demonstration's windings
///   (the caller gives the grasp with them: transfer_shuffled(), grasp_transfer's partner rule).
///
/// The baselines place the hand without a plan: autoclose (the paper's baseline: the target's
/// palm at the source's palm, its usual pre-shape, closed), transplant (a fairer one: the grasp
/// centres paired, the hand opened by transplant_opening), fingertip and virtual_finger.
enum class TransferMethod : std::uint8_t {
  topological,
  transplant,
  fingertip,
  paper,
  paper_line,
  paper_approach,
  no_windings,
  nearest_point,
  virtual_finger,
  closed_windings,
  no_plan,
  shuffled_windings,
  autoclose
};

/// Every transfer method, in the order --help lists them.
inline constexpr std::array<TransferMethod, 13> all_transfer_methods{
    TransferMethod::topological,      TransferMethod::autoclose,       TransferMethod::transplant,
    TransferMethod::fingertip,        TransferMethod::virtual_finger,  TransferMethod::paper,
    TransferMethod::paper_line,       TransferMethod::paper_approach,  TransferMethod::no_windings,
    TransferMethod::nearest_point,    TransferMethod::closed_windings, TransferMethod::no_plan,
    TransferMethod::shuffled_windings};

/// The name of \p m ("topological", "autoclose", "transplant", "fingertip", "virtual_finger",
/// "paper", "paper_line", "paper_approach", "no_windings", "nearest_point", "closed_windings",
/// "no_plan", "shuffled_windings").
[[nodiscard]] constexpr std::string_view to_string(TransferMethod m) noexcept {
  switch (m) {
    case TransferMethod::topological:
      return "topological";
    case TransferMethod::transplant:
      return "transplant";
    case TransferMethod::fingertip:
      return "fingertip";
    case TransferMethod::paper:
      return "paper";
    case TransferMethod::paper_line:
      return "paper_line";
    case TransferMethod::paper_approach:
      return "paper_approach";
    case TransferMethod::no_windings:
      return "no_windings";
    case TransferMethod::nearest_point:
      return "nearest_point";
    case TransferMethod::virtual_finger:
      return "virtual_finger";
    case TransferMethod::closed_windings:
      return "closed_windings";
    case TransferMethod::no_plan:
      return "no_plan";
    case TransferMethod::shuffled_windings:
      return "shuffled_windings";
    case TransferMethod::autoclose:
      return "autoclose";
  }
  return "unknown";
}

/// Whether \p m is the topological method or one of its named variants (transfer_topological).
[[nodiscard]] constexpr bool is_topological(TransferMethod m) noexcept {
  return m != TransferMethod::autoclose && m != TransferMethod::transplant &&
         m != TransferMethod::fingertip && m != TransferMethod::virtual_finger;
}

/// The method called \p name (to_string of one of all_transfer_methods).
/// \throws topograsp::invalid_argument naming "method" for any other name.
[[nodiscard]] inline TransferMethod transfer_method(std::string_view name) {
  for (const TransferMethod m : all_transfer_methods)
    if (to_string(m) == name) return m;
  std::string expected;
  for (std::size_t i = 0; i < all_transfer_methods.size(); ++i)
    expected += std::string(i == 0                                 ? ""
                            : i + 1 == all_transfer_methods.size() ? " or "
                                                                   : ", ") +
                std::string(to_string(all_transfer_methods[i]));
  detail::throw_invalid_argument(
      "method", "unknown method \"" + std::string(name) + "\" (expected " + expected + ")");
}
}  // namespace topograsp
