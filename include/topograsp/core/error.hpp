// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The error types of topograsp and the run-time argument checks that throw them.
#pragma once

#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>

#include <topograsp/core/eigen.hpp>

namespace topograsp {

/// Thrown for a non-finite or wrongly sized run-time input at a public entry point. The message
/// starts with the name of the offending argument: "<argument>: <problem>".
class invalid_argument : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
  /// The error "<argument>: <problem>" about \p argument.
  invalid_argument(std::string_view argument, std::string_view problem)
      : std::invalid_argument(message(argument, problem)), problem_offset_(argument.size() + 2) {}
  /// The name of the offending argument ("" for an error made from a whole message).
  [[nodiscard]] std::string_view argument() const noexcept {
    return problem_offset_ == 0 ? std::string_view()
                                : std::string_view(what(), problem_offset_ - 2);
  }
  /// What is wrong with argument() (the whole message for an error made from one).
  [[nodiscard]] std::string_view problem() const noexcept { return what() + problem_offset_; }

 private:
  static std::string message(std::string_view argument, std::string_view problem) {
    std::string m(argument);
    m += ": ";
    m += problem;
    return m;
  }
  std::size_t problem_offset_ = 0;  // where the problem starts in what(); 0 without an argument
};

namespace detail {

// "FILE:LINE: problem", or "FILE: problem" for line 0 (no line applies): the message of a file
// reader's error (xml_error, mesh_error). Appended piece by piece (GCC 12 warns of a false
// -Wrestrict in ":" + std::string&&).
inline std::string file_line_message(const std::string& file, int line,
                                     const std::string& problem) {
  std::string m = file;
  if (line > 0) {
    m += ':';
    m += std::to_string(line);
  }
  m += ": ";
  m += problem;
  return m;
}

[[noreturn]] inline void throw_invalid_argument(std::string_view argument, std::string_view what) {
  throw invalid_argument(argument, what);
}

}  // namespace detail

/// The value of \p values whose to_string() is \p name. Throws topograsp::invalid_argument naming
/// \p argument otherwise, with the message 'unknown <noun> "<name>" (expected a, b or c)'. The one
/// parser of the library's named enums (each has a constexpr to_string() beside it).
template <class Enum>
[[nodiscard]] Enum enum_from_name(std::string_view name, std::initializer_list<Enum> values,
                                  std::string_view argument, std::string_view noun) {
  std::string expected;
  std::size_t i = 0;
  for (const Enum e : values) {
    if (to_string(e) == name) return e;
    expected += i == 0 ? "" : (i + 1 == values.size() ? " or " : ", ");
    expected += to_string(e);
    ++i;
  }
  detail::throw_invalid_argument(argument, "unknown " + std::string(noun) + " \"" +
                                               std::string(name) + "\" (expected " + expected +
                                               ")");
}

/// Throws topograsp::invalid_argument naming \p argument unless \p value is finite.
inline void require_finite(double value, std::string_view argument) {
  if (!std::isfinite(value)) detail::throw_invalid_argument(argument, "expected a finite number");
}

/// Throws topograsp::invalid_argument naming \p argument unless \p value is finite and > 0.
inline void require_positive(double value, std::string_view argument) {
  if (!std::isfinite(value) || !(value > 0.0))
    detail::throw_invalid_argument(argument,
                                   "expected a finite number > 0, got " + std::to_string(value));
}

/// Throws topograsp::invalid_argument naming \p argument unless \p value is finite and >= 0.
inline void require_non_negative(double value, std::string_view argument) {
  if (!std::isfinite(value) || value < 0.0)
    detail::throw_invalid_argument(argument,
                                   "expected a finite number >= 0, got " + std::to_string(value));
}

/// Throws topograsp::invalid_argument naming \p argument unless every entry of \p m is finite.
template <EigenDense D>
void require_finite(const D& m, std::string_view argument) {
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      if (!std::isfinite(m(i, j)))
        detail::throw_invalid_argument(argument, "expected finite entries, entry (" +
                                                     std::to_string(i) + ", " + std::to_string(j) +
                                                     ") is " + std::to_string(m(i, j)));
}

/// Throws topograsp::invalid_argument naming \p argument unless \p m has \p rows entries.
template <EigenDense D>
void require_size(const D& m, Eigen::Index rows, std::string_view argument) {
  if (m.rows() != rows || m.cols() != 1)
    detail::throw_invalid_argument(argument, "expected a vector of size " + std::to_string(rows) +
                                                 ", got " + std::to_string(m.rows()) + "x" +
                                                 std::to_string(m.cols()));
}

}  // namespace topograsp
