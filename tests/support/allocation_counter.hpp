// SPDX-License-Identifier: BSD-3-Clause
// A count of every heap allocation, for the tests that a hot path allocates nothing: replaces the
// global operator new. Include it in exactly ONE translation unit of a test executable (it
// defines the replacement functions). Eigen's own run-time guard (EIGEN_RUNTIME_NO_MALLOC, which
// tests/CMakeLists.txt defines for every test executable) checks the same from the other side.
#pragma once

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

namespace topograsp::test {

namespace detail {
inline std::atomic<long> allocations{0};
inline const void* volatile allocation_sink = nullptr;  // keeps a test allocation observable
}  // namespace detail

/// The number of operator new calls so far in this executable.
inline long allocations() noexcept { return detail::allocations.load(std::memory_order_relaxed); }

/// True if one std::vector allocation moves the counter by exactly one: the check that a test
/// comparing allocations() before and after can fail.
inline bool allocation_counter_counts() {
  const long before = allocations();
  {
    std::vector<double> v;
    v.reserve(16);
    detail::allocation_sink = v.data();
  }
  return allocations() == before + 1;
}

}  // namespace topograsp::test

// Under AddressSanitizer, a few allocations made inside the sanitizer's own runtime reach its
// operator new but our operator delete (which frees with free()); the pair is consistent for every
// allocation the executable makes, so the mismatch check is off for the executable.
extern "C" const char* __asan_default_options();
extern "C" const char* __asan_default_options() { return "alloc_dealloc_mismatch=0"; }

// GCC flags free() on memory from (this very) operator new; the pair is consistent by design.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  topograsp::test::detail::allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
