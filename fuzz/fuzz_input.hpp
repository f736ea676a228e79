// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The fuzz targets' common helpers: FuzzInput turns libFuzzer's bytes into numbers, choices and
/// rotations (clang's FuzzedDataProvider underneath: when the bytes run out every value is its
/// range's low end, so every input is valid), and fuzz_fail() prints what failed with the input
/// values and aborts, which libFuzzer records as a crash with its reproducer.
#pragma once

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <set>
#include <string>
#include <string_view>

#include <Eigen/Geometry>

namespace topograsp::fuzz {

/// \p s as a C++ string literal, so that every byte of a failing input is visible.
inline std::string c_literal(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || u >= 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", u);
      out += buf;
      // A hex escape swallows the hex digits after it: end the literal there.
      out += "\" \"";
    } else {
      out += c;
    }
  }
  out += '"';
  return out;
}

/// Reads the values of one fuzz input from its bytes.
class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : p_(data, size) {}

  /// An integer in [lo, hi].
  int integer(int lo, int hi) { return p_.ConsumeIntegralInRange<int>(lo, hi); }
  bool flag() { return p_.ConsumeBool(); }
  /// One of \p options.
  template <class T>
  T pick(std::initializer_list<T> options) {
    return *(options.begin() + integer(0, static_cast<int>(options.size()) - 1));
  }
  /// A real in [lo, hi] (both finite).
  double real(double lo, double hi) { return p_.ConsumeFloatingPointInRange<double>(lo, hi); }
  /// Any finite double, from the whole range (huge, tiny, zero, negative).
  double any_finite() { return p_.ConsumeFloatingPoint<double>(); }
  /// A positive number m 10^e with m in [1, 10) and e an integer in [lo_exp, hi_exp].
  double magnitude(int lo_exp, int hi_exp) {
    const int e = integer(lo_exp, hi_exp);
    return real(1.0, 9.999) * std::pow(10.0, e);
  }
  /// A vector with entries in [lo, hi].
  Eigen::Vector3d vec(double lo, double hi) {
    const double x = real(lo, hi), y = real(lo, hi), z = real(lo, hi);
    return {x, y, z};
  }
  /// A rotation from a quaternion of four reals in [-1, 1] (the identity for a zero one).
  Eigen::Matrix3d rotation() {
    Eigen::Vector4d q;
    for (int k = 0; k < 4; ++k) q[k] = real(-1.0, 1.0);
    if (!(q.norm() > 1e-6)) return Eigen::Matrix3d::Identity();
    q.normalize();
    return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
  }
  [[nodiscard]] std::size_t remaining() { return p_.remaining_bytes(); }

 private:
  FuzzedDataProvider p_;
};

/// \p x with 17 significant digits (round-trips).
inline std::string num(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
inline std::string vec_str(const Eigen::Vector3d& v) {
  return "(" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + ")";
}
inline std::string mat_str(const Eigen::Matrix3d& m) {
  return "[" + vec_str(m.row(0).transpose()) + ", " + vec_str(m.row(1).transpose()) + ", " +
         vec_str(m.row(2).transpose()) + "]";
}

namespace detail {
/// The bytes of the input being run (for the survey mode's reproducers).
inline const std::uint8_t* current_data = nullptr;
inline std::size_t current_size = 0;
/// Thrown by fuzz_fail() in survey mode, caught by run_input(); not a std::exception, so that no
/// handler of a target takes it for the library's.
struct SurveyedFailure {};

/// \p what with every number replaced by '#', every quoted text by "" and the insides of
/// parentheses and brackets (vectors, matrices) left out: failures of one kind share it.
inline std::string failure_kind(std::string_view target, std::string_view what) {
  std::string kind(target);
  kind += ": ";
  bool in_number = false;
  int depth = 0;
  for (std::size_t i = 0; i < what.size(); ++i) {
    const char c = what[i];
    if (c == '(' || c == '[') {
      if (depth++ == 0) kind += c;
      continue;
    }
    if (c == ')' || c == ']') {
      if (depth > 0 && --depth == 0) kind += c;
      continue;
    }
    if (depth > 0) continue;
    if (c == '"') {
      for (++i; i < what.size() && what[i] != '"'; ++i)
        if (what[i] == '\\') ++i;
      kind += "\"\"";
      in_number = false;
      continue;
    }
    const bool digit = (c >= '0' && c <= '9') || (c == '-' && i + 1 < what.size() &&
                                                  what[i + 1] >= '0' && what[i + 1] <= '9');
    const bool part = digit || (in_number && (c == '.' || c == 'e' || c == '-' || c == '+'));
    if (part) {
      if (!in_number) kind += '#';
      in_number = true;
    } else {
      in_number = false;
      kind += c;
    }
  }
  return kind;
}
}  // namespace detail

/// Runs one input: \p body reads and checks it. In survey mode a failure ends only this input.
template <class F>
int run_input(const std::uint8_t* data, std::size_t size, F&& body) {
  detail::current_data = data;
  detail::current_size = size;
  try {
    body();
  } catch (const detail::SurveyedFailure&) {
  }
  return 0;
}

/// Prints "FUZZ FAILURE in <target>: <what>" and the input's values, then aborts (a libFuzzer
/// crash, whose reproducer libFuzzer saves).
///
/// Survey mode, for long runs on code with known failures: with the environment variable
/// TOPOGRASP_FUZZ_SURVEY set to a folder, the first failure of each kind (the message with its
/// numbers left out) is printed as "FUZZ SURVEY" and its input saved there as <target>-<n>; then
/// the input ends and fuzzing goes on, so that one frequent failure does not hide the others.
/// Sanitizer reports still abort.
[[noreturn]] inline void fuzz_fail(std::string_view target, std::string_view what,
                                   std::string_view input) {
  if (const char* dir = std::getenv("TOPOGRASP_FUZZ_SURVEY"); dir != nullptr && *dir != 0) {
    static std::set<std::string> seen;
    if (seen.insert(detail::failure_kind(target, what)).second) {
      const std::string path =
          std::string(dir) + "/" + std::string(target) + "-" + std::to_string(seen.size());
      if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
        if (detail::current_size > 0) std::fwrite(detail::current_data, 1, detail::current_size, f);
        std::fclose(f);
      }
      std::fprintf(stderr, "\nFUZZ SURVEY %s (kind %zu) in %.*s: %.*s\ninput:\n%.*s\n",
                   path.c_str(), seen.size(), static_cast<int>(target.size()), target.data(),
                   static_cast<int>(what.size()), what.data(), static_cast<int>(input.size()),
                   input.data());
    }
    throw detail::SurveyedFailure{};
  }
  std::fprintf(stderr, "\nFUZZ FAILURE in %.*s: %.*s\ninput:\n%.*s\n",
               static_cast<int>(target.size()), target.data(), static_cast<int>(what.size()),
               what.data(), static_cast<int>(input.size()), input.data());
  std::abort();
}

}  // namespace topograsp::fuzz
