// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// TOPOGRASP_ASSERT(condition, message): a check of an internal invariant, one that no input of
/// the user can break (bad input is rejected by the API with topograsp::invalid_argument).
///
/// On when NDEBUG is not defined (Debug and the sanitizer build), off otherwise (Release). Define
/// TOPOGRASP_ENABLE_ASSERTS to 1 or 0 before the first include (or with -D) to force it on or off
/// in every build type; use the same setting in every translation unit of a program. When off,
/// the condition is not evaluated (it is still compiled, so it cannot rot). A failure calls
/// TOPOGRASP_ASSERT_HANDLER(file, line, condition, message) (like the switch, define it the same
/// way in every translation unit: inline functions that assert must not differ), by default
/// topograsp::detail::assertion_failed(), which prints "file:line: TOPOGRASP_ASSERT(condition)
/// failed: message" to stderr and aborts.
#pragma once

#include <cstdio>
#include <cstdlib>

#ifndef TOPOGRASP_ENABLE_ASSERTS
#ifdef NDEBUG
#define TOPOGRASP_ENABLE_ASSERTS 0
#else
#define TOPOGRASP_ENABLE_ASSERTS 1
#endif
#endif

namespace topograsp::detail {

/// Prints where and which internal invariant failed, then aborts.
[[noreturn]] inline void assertion_failed(const char* file, int line, const char* condition,
                                          const char* message) noexcept {
  std::fprintf(stderr, "%s:%d: TOPOGRASP_ASSERT(%s) failed: %s\n", file, line, condition, message);
  std::fflush(stderr);
  std::abort();
}

}  // namespace topograsp::detail

#ifndef TOPOGRASP_ASSERT_HANDLER
#define TOPOGRASP_ASSERT_HANDLER ::topograsp::detail::assertion_failed
#endif

/// The checking form, whatever the configuration.
#define TOPOGRASP_ASSERT_CHECK(condition, message) \
  (static_cast<bool>(condition)                    \
       ? static_cast<void>(0)                      \
       : TOPOGRASP_ASSERT_HANDLER(__FILE__, __LINE__, #condition, message))
/// The disabled form: compiles the condition without evaluating it.
#define TOPOGRASP_ASSERT_IGNORE(condition, message) \
  (static_cast<void>(sizeof(static_cast<bool>(condition))), static_cast<void>(sizeof(message)))

#if TOPOGRASP_ENABLE_ASSERTS
#define TOPOGRASP_ASSERT(condition, message) TOPOGRASP_ASSERT_CHECK(condition, message)
#else
#define TOPOGRASP_ASSERT(condition, message) TOPOGRASP_ASSERT_IGNORE(condition, message)
#endif
