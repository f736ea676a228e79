// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Parameter tables: the numeric fields of an options struct by name, with their valid ranges and
/// meanings. One table per options struct drives its checks (validate_parameters), the command
/// line's `--set NAME=VALUE` (set_parameter), a results file's record of the options and the
/// `--help` text (parameter_help).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include <topograsp/core/error.hpp>
#include <topograsp/core/number_text.hpp>

namespace topograsp {

/// The upper end of a parameter's range that has none (every finite value above min).
inline constexpr double unbounded = std::numeric_limits<double>::infinity();

/// One numeric field of an options struct \p Options: its name, the member (a double or an int),
/// its valid range and a one-line meaning with its unit. The range is [min, max], or (min, max]
/// when above_min; max infinity admits every finite value above min. An int field takes only
/// whole values.
template <class Options>
struct Parameter {
  std::string_view name;
  std::variant<double Options::*, int Options::*> field;
  double min;
  double max;
  std::string_view meaning;
  bool above_min = false;  ///< the range excludes min ("> 0" rather than ">= 0")

  /// The field's value in \p options.
  [[nodiscard]] constexpr double get(const Options& options) const {
    return std::visit([&](auto member) { return static_cast<double>(options.*member); }, field);
  }
  /// Sets the field in \p options to \p value as it is (no range check: set_parameter checks;
  /// an int field takes the value truncated).
  constexpr void assign(Options& options, double value) const {
    std::visit(
        [&](auto member) {
          using T = std::remove_reference_t<decltype(options.*member)>;
          options.*member = static_cast<T>(value);
        },
        field);
  }
  /// Whether the field is an int.
  [[nodiscard]] constexpr bool integer() const noexcept { return field.index() == 1; }
};

/// A parameter table: every numeric field of \p Options that is set by name, in the order --help
/// lists them.
template <class Options, std::size_t N>
using ParameterTable = std::array<Parameter<Options>, N>;

/// The range of \p p as messages and --help print it: "[0, 0.3]", "(0, 1]", "[1, 1e+06]",
/// "(0, inf)".
template <class Options>
[[nodiscard]] std::string parameter_range(const Parameter<Options>& p) {
  return (p.above_min ? "(" : "[") + detail::number_text(p.min) + ", " +
         detail::number_text(p.max) + (std::isinf(p.max) ? ")" : "]");
}

/// Checks \p value against \p p's range (NaN, infinity and, for an int field, a fraction are
/// outside it).
/// \throws topograsp::invalid_argument naming \p prefix followed by p.name, with the range and
/// the meaning, if it is outside.
template <class Options>
void check_parameter(const Parameter<Options>& p, double value, std::string_view prefix = "") {
  const bool low_ok = p.above_min ? value > p.min : value >= p.min;
  const bool whole = !p.integer() || value == std::floor(value);
  if (!(std::isfinite(value) && low_ok && value <= p.max && whole))
    detail::throw_invalid_argument(
        std::string(prefix) + std::string(p.name),
        "must be in " + parameter_range(p) + (p.integer() ? ", a whole number" : "") + " (" +
            std::string(p.meaning) + "), got " + detail::number_text(value));
}

/// Checks every field of \p table in \p options (check_parameter), in table order; messages name
/// the field after \p prefix (e.g. "options.").
/// \throws topograsp::invalid_argument naming the first field out of its range.
template <class Options, std::size_t N>
void validate_parameters(const Options& options, const ParameterTable<Options, N>& table,
                         std::string_view prefix = "") {
  for (const Parameter<Options>& p : table) check_parameter(p, p.get(options), prefix);
}

/// The entry of \p table called \p name, or nullptr.
template <class Options, std::size_t N>
[[nodiscard]] constexpr const Parameter<Options>* find_parameter(
    const ParameterTable<Options, N>& table, std::string_view name) noexcept {
  for (const Parameter<Options>& p : table)
    if (p.name == name) return &p;
  return nullptr;
}

/// Sets the field called \p name of \p table in \p options to \p value; \p options is unchanged
/// if it throws.
/// \throws topograsp::invalid_argument naming "name" if \p table has no such field (the message
/// says 'unknown <noun> "<name>"' and lists the names), or naming the field if \p value is
/// outside its range.
template <class Options, std::size_t N>
void set_parameter(Options& options, const ParameterTable<Options, N>& table, std::string_view name,
                   double value, std::string_view noun = "parameter") {
  const Parameter<Options>* p = find_parameter(table, name);
  if (p == nullptr) {
    std::string names;
    for (const Parameter<Options>& q : table)
      names += (names.empty() ? "" : ", ") + std::string(q.name);
    detail::throw_invalid_argument("name", "unknown " + std::string(noun) + " \"" +
                                               std::string(name) + "\" (expected one of " + names +
                                               ")");
  }
  check_parameter(*p, value);
  p->assign(options, value);
}

/// The rows of a --help table of \p table: name, the value in \p defaults, the range and the
/// meaning, one line each, indented by two spaces, with a header line.
template <class Options, std::size_t N>
[[nodiscard]] std::string parameter_help(const ParameterTable<Options, N>& table,
                                         const Options& defaults) {
  char line[256];
  std::snprintf(line, sizeof line, "  %-24s %-9s %-12s %s\n", "name", "default", "range",
                "meaning");
  std::string text = line;
  for (const Parameter<Options>& p : table) {
    std::snprintf(line, sizeof line, "  %-24s %-9s %-12s %s\n", std::string(p.name).c_str(),
                  detail::number_text(p.get(defaults)).c_str(), parameter_range(p).c_str(),
                  std::string(p.meaning).c_str());
    text += line;
  }
  return text;
}

}  // namespace topograsp
