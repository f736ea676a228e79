// SPDX-License-Identifier: BSD-3-Clause
// A program whose internal invariant fails, run by CTest (tests/CMakeLists.txt): with assertions
// on it must print "file:line: TOPOGRASP_ASSERT(condition) failed: message" and abort; with them
// off it must not evaluate the condition. The abort is turned into a normal exit so that CTest
// judges the output alone.
#include <csignal>
#include <cstdio>
#include <cstdlib>

#include <topograsp/core/assert.hpp>

extern "C" void on_abort(int /*signal*/) { std::_Exit(0); }

// External linkage: with assertions off the condition is only compiled (inside sizeof), and clang
// warns that an internal function used only there is never emitted.
int evaluated = 0;
bool count_and_fail();
bool count_and_fail() { return ++evaluated == 2; }

int main() {
  std::signal(SIGABRT, on_abort);
  TOPOGRASP_ASSERT(count_and_fail(), "the probe's invariant");
  std::printf("TOPOGRASP_ASSERT is off (condition evaluated %d times)\n", evaluated);
  return evaluated == 0 ? 0 : 1;
}
