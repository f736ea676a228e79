// SPDX-License-Identifier: BSD-3-Clause
// TOPOGRASP_ASSERT: on exactly when NDEBUG is not defined (unless forced), a failure reaches the
// handler with the file, line and condition, and the disabled form does not evaluate.
// This translation unit includes no other library header, so its own handler changes nothing
// elsewhere in the program.
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

namespace {

struct AssertionFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void throwing_handler(const char* file, int line, const char* condition,
                                   const char* message) {
  throw AssertionFailure(std::string(file) + ":" + std::to_string(line) + ": " + condition + ": " +
                         message);
}

}  // namespace

#define TOPOGRASP_ASSERT_HANDLER throwing_handler
#include <topograsp/core/assert.hpp>

TEST_CASE("TOPOGRASP_ASSERT is on exactly in builds without NDEBUG", "[core][assert]") {
#ifdef NDEBUG
  STATIC_REQUIRE(TOPOGRASP_ENABLE_ASSERTS == 0);
#else
  STATIC_REQUIRE(TOPOGRASP_ENABLE_ASSERTS == 1);
#endif
}

TEST_CASE("a failed check reaches the handler with file, line and condition", "[core][assert]") {
  int evaluated = 0;
  const int line = __LINE__ + 2;
  try {
    TOPOGRASP_ASSERT_CHECK(++evaluated == 2, "the test's invariant");
    FAIL("the handler was not called");
  } catch (const AssertionFailure& e) {
    const std::string what = e.what();
    CHECK(what.find("test_assert.cpp:" + std::to_string(line) + ": ") != std::string::npos);
    CHECK(what.find("++evaluated == 2: the test's invariant") != std::string::npos);
  }
  CHECK(evaluated == 1);
  CHECK_NOTHROW(TOPOGRASP_ASSERT_CHECK(evaluated == 1, "holds"));
}

TEST_CASE("the disabled form does not evaluate its condition", "[core][assert]") {
  int evaluated = 0;
  const auto count = [&evaluated] { return ++evaluated == 2; };
  TOPOGRASP_ASSERT_IGNORE(count(), "never checked");
  CHECK(evaluated == 0);
}

TEST_CASE("TOPOGRASP_ASSERT follows the configuration", "[core][assert]") {
  int evaluated = 0;
  const auto count = [&evaluated] { return ++evaluated == 2; };
  bool fired = false;
  try {
    TOPOGRASP_ASSERT(count(), "fires when on");
  } catch (const AssertionFailure&) {
    fired = true;
  }
  CHECK(fired == (TOPOGRASP_ENABLE_ASSERTS == 1));
  CHECK(evaluated == TOPOGRASP_ENABLE_ASSERTS);
}
