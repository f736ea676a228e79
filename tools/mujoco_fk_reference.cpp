// SPDX-License-Identifier: BSD-3-Clause
// mujoco_fk_reference: MuJoCo's forward kinematics of a model file at seeded configurations, the
// reference the shipped hands are checked against (tests/hands/data/*_fk_reference.json,
// docs/models.md "Today's hands"). Built where MuJoCo is found.
//
//   mujoco_fk_reference FILE OUT.json [N] [SEED]
//
// Configuration 0: every hinge and slide joint at 0, clamped into its range; configurations 1 to
// N-1 (N = 16): each joint in qpos order uniform in its range (unlimited hinges [-pi, pi]),
// u = (mt19937_64(SEED) >> 11) 2^-53, q = lo + u (hi - lo). Then mj_kinematics; every body's
// position and orientation (w, x, y, z) in the world, with the root body where the file puts it.
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include <mujoco/mujoco.h>
#include <topograsp/io/json.hpp>
#include <topograsp/io/text_file.hpp>

namespace {

topograsp::Json numbers(const double* v, int n) {
  topograsp::Json a = topograsp::Json::array();
  for (int i = 0; i < n; ++i) a.push_back(v[i]);
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 5) {
    std::fprintf(stderr, "usage: mujoco_fk_reference FILE OUT.json [N] [SEED]\n");
    return 2;
  }
  const int n = argc > 3 ? std::atoi(argv[3]) : 16;
  const unsigned long long seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
  if (n < 1) {
    std::fprintf(stderr, "mujoco_fk_reference: N must be at least 1\n");
    return 2;
  }
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], nullptr, error, sizeof error);
  if (!m) {
    std::fprintf(stderr, "mujoco_fk_reference: %s: %s\n", argv[1], error);
    return 1;
  }
  mjData* d = mj_makeData(m);
  using topograsp::Json;
  Json doc = Json::object();
  doc.set("source", std::string_view(argv[1]));
  doc.set("mujoco_version", std::string_view(mj_versionString()));
  doc.set("seed", static_cast<double>(seed));
  Json joints = Json::array(), bodies_of_joints = Json::array();
  for (int j = 0; j < m->njnt; ++j) {  // joint ids are in qpos order
    joints.push_back(std::string_view(m->names + m->name_jntadr[j]));
    bodies_of_joints.push_back(std::string_view(m->names + m->name_bodyadr[m->jnt_bodyid[j]]));
  }
  doc.set("joints", joints);
  doc.set("joint_bodies", bodies_of_joints);
  std::mt19937_64 rng(seed);
  Json configs = Json::array();
  for (int c = 0; c < n; ++c) {
    mju_copy(d->qpos, m->qpos0, m->nq);
    for (int j = 0; j < m->njnt; ++j) {
      const int type = m->jnt_type[j];
      if (type != mjJNT_HINGE && type != mjJNT_SLIDE) continue;
      const bool limited = m->jnt_limited[j] != 0;
      const double lo = limited ? m->jnt_range[2 * j] : (type == mjJNT_HINGE ? -mjPI : -1.0);
      const double hi = limited ? m->jnt_range[2 * j + 1] : (type == mjJNT_HINGE ? mjPI : 1.0);
      const double u = static_cast<double>(rng() >> 11) * 0x1p-53;
      d->qpos[m->jnt_qposadr[j]] =
          c == 0 ? (0.0 < lo ? lo : (0.0 > hi ? hi : 0.0)) : lo + u * (hi - lo);
    }
    mj_kinematics(m, d);
    Json config = Json::object(), bodies = Json::object();
    config.set("qpos", numbers(d->qpos, m->nq));
    for (int b = 1; b < m->nbody; ++b) {
      Json body = Json::object();
      body.set("pos", numbers(d->xpos + 3 * b, 3));
      body.set("quat", numbers(d->xquat + 4 * b, 4));
      bodies.set(m->names + m->name_bodyadr[b], body);
    }
    config.set("bodies", bodies);
    configs.push_back(config);
  }
  doc.set("configs", configs);
  mj_deleteData(d);
  mj_deleteModel(m);
  try {  // a temporary file, then renamed: a failed run leaves no half-written reference
    std::string text = doc.dump(1);
    text += '\n';
    topograsp::detail::write_text_file(argv[2], text);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mujoco_fk_reference: %s\n", e.what());
    return 1;
  }
  return 0;
}
