// SPDX-License-Identifier: BSD-3-Clause
// MJCF export: the text names the mocap hand and the free object with its mass and inertia; with
// MuJoCo found, the file loads back and matches the scene.
#include "evaluation_test_support.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>
#include <topograsp/io/mjcf.hpp>

#ifdef TOPOGRASP_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

using namespace topograsp;

TEST_CASE("a hand scene exports as MJCF with a mocap hand and a free object",
          "[evaluation][mjcf]") {
  auto scene = test::sdh_bottle_scene(0.9);
  REQUIRE(close_hand(scene).status == Status::success);
  const std::string xml = to_mjcf(scene);
  CHECK(xml.find("<mujoco model=\"schunk_sdh\">") != std::string::npos);
  CHECK(xml.find("<body name=\"hand\" mocap=\"true\"") != std::string::npos);
  CHECK(xml.find("<body name=\"object\"") != std::string::npos);
  CHECK(xml.find("type=\"free\"") != std::string::npos);
  CHECK(xml.find("mass=\"0.5\"") != std::string::npos);
  CHECK(xml.find("friction=\"0.9 ") != std::string::npos);
  CHECK(xml.find("cone=\"elliptic\"") != std::string::npos);
  CHECK(xml.find("nan") == std::string::npos);

#ifdef TOPOGRASP_HAVE_MUJOCO
  const auto path = std::filesystem::temp_directory_path() /
                    ("topograsp_mjcf_test_" + std::to_string(::getpid()) + ".xml");
  {
    std::ofstream f(path);
    f << xml;
  }
  char error[1000] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof(error));
  std::filesystem::remove(path);
  INFO(error);
  REQUIRE(m != nullptr);
  const auto& world = scene.world();
  CHECK(m->nbody == 3);  // world, hand, object
  CHECK(m->nmocap == 1);
  CHECK(m->ngeom == world.collider_count());
  CHECK(m->opt.timestep == Approx(1.0 / 60.0));
  const int object = mj_name2id(m, mjOBJ_BODY, "object");
  REQUIRE(object >= 0);
  CHECK(m->body_mass[object] == Approx(0.5));
  // Principal moments of the bottle (a cylinder): m r^2 / 2 and m (3 r^2 + (2h)^2) / 12.
  std::array<double, 3> I{m->body_inertia[3 * object], m->body_inertia[3 * object + 1],
                          m->body_inertia[3 * object + 2]};
  std::sort(I.begin(), I.end());
  const double r = 0.035, h = 0.1;
  CHECK(I[0] == Approx(0.5 * r * r / 2).epsilon(1e-6));
  CHECK(I[2] == Approx(0.5 * (3 * r * r + 4 * h * h) / 12).epsilon(1e-6));
  // The object starts where the scene has it.
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  const Eigen::Vector3d com = world.body(scene.object_body()).x;
  for (int k = 0; k < 3; ++k) CHECK(d->xipos[3 * object + k] == Approx(com[k]).margin(1e-9));
  // The hand geoms are where the scene has them (the first capsule of the first link with one).
  for (int c = 0; c < world.collider_count(); ++c) {
    const auto& col = world.collider(c);
    if (world.body(col.body).type != BodyType::kinematic) continue;
    const int gid = mj_name2id(m, mjOBJ_GEOM, ("hand_" + std::to_string(c)).c_str());
    REQUIRE(gid >= 0);
    for (int k = 0; k < 3; ++k) CHECK(d->geom_xpos[3 * gid + k] == Approx(col.p[k]).margin(1e-9));
  }
  // MuJoCo finds the hand touching the bottle.
  CHECK(d->ncon > 0);
  mj_deleteData(d);
  mj_deleteModel(m);
#endif
}
