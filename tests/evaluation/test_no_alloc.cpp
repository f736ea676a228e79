// SPDX-License-Identifier: BSD-3-Clause
// Once a scene is built, stepping it allocates nothing: counted with a replaced global operator
// new and checked by Eigen's run-time malloc guard (EIGEN_RUNTIME_NO_MALLOC, defined for the whole
// executable by evaluation_test_support.hpp). Also: the float instantiation compiles and runs.
#include "evaluation_test_support.hpp"

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include <catch2/catch.hpp>

namespace {
std::atomic<long> allocations{0};
const void* volatile sink = nullptr;  // makes an allocation observable, so it is not elided
}  // namespace

// Under AddressSanitizer, a few allocations made inside the sanitizer's own runtime reach its
// operator new but our operator delete (which frees with free()); the pair is consistent for every
// allocation this executable makes, so the mismatch check is off for this test executable only.
extern "C" const char* __asan_default_options();
extern "C" const char* __asan_default_options() { return "alloc_dealloc_mismatch=0"; }

// GCC flags free() on memory from (this very) operator new; the pair is consistent by design.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t n) {
  allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n == 0 ? 1 : n)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

using namespace topograsp;

// Explicit instantiation: every member of the hand scene compiles for float (the stepper's own
// instantiations are in tests/physics/test_instantiation.cpp).
template class topograsp::HandScene<models::schunk_sdh, float>;

TEST_CASE("stepping a built scene and shaking it allocate nothing", "[evaluation][alloc]") {
  auto scene = test::sdh_bottle_scene(1.0);
  REQUIRE(close_hand(scene).status == Status::success);
  const long before = allocations.load();
  Eigen::internal::set_is_malloc_allowed(false);
  Status s = Status::success;
  for (int i = 0; i < 50; ++i) s = scene.step();
  const ShakeResult r = shake_test(scene);
  Eigen::internal::set_is_malloc_allowed(true);
  const long after = allocations.load();
  CHECK(s == Status::success);
  CHECK(r.stable);
  CHECK(after == before);
  // The counter does count (so the check above can fail).
  {
    std::vector<double> v;
    v.reserve(16);
    sink = v.data();
  }
  CHECK(allocations.load() == after + 1);
}

TEST_CASE("the float stepper holds a box and a grasp", "[evaluation][float]") {
  World<float> w;
  static const std::array<ShapeSpec, 1> ground{box("", at(0, 0, -0.5), {20.0, 20.0, 0.5})};
  static const std::array<ShapeSpec, 1> cube{box("", Pose{}, {0.1, 0.1, 0.1})};
  BodyDesc g;
  g.type = BodyType::fixed;
  g.shapes = ground;
  w.add_body(g);
  BodyDesc b;
  b.pose = at(0, 0, 0.1);
  b.shapes = cube;
  b.mass = 1.0;
  const int box_id = w.add_body(b);
  for (int i = 0; i < 120; ++i) REQUIRE(w.step() == Status::success);
  CHECK(std::abs(w.body(box_id).x.z() - 0.1f) < 1e-3f);
  CHECK(w.kinetic_energy() < 1e-6f);

  const Eigen::Isometry3d hand = test::sdh_side_pose();
  Vec<7> q;
  q << 0.0, -0.6, 0.3, -0.6, 0.3, -0.6, 0.3;
  HandScene<models::schunk_sdh, float> scene(
      hand, q,
      test::cylinder_object(hand, Eigen::Vector3d(0, 0, 0.15), Eigen::Vector3d::UnitY(), 0.035, 0.1,
                            0.5));
  REQUIRE(close_hand(scene).status == Status::success);
  const ShakeResult r = shake_test(scene);
  CHECK(r.stable);
}
