// SPDX-License-Identifier: BSD-3-Clause
// Today's hands, shipped (models/allegro_hand.hpp, leap_hand.hpp, shadow_hand.hpp): each has the
// forward kinematics MuJoCo 2.2.2 computed on its source file
// (tests/hands/data/*_fk_reference.json, 16 configurations: every body's position and orientation
// in the root's frame); each joint that closes moves its digit's tip toward the space in front of
// the palm; each is a hand with a thumb and torque limits on every actuated joint.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>
#include <topograsp/io/json.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/model/models/allegro_hand.hpp>
#include <topograsp/model/models/leap_hand.hpp>
#include <topograsp/model/models/shadow_hand.hpp>

using namespace topograsp;

namespace {

Json read_reference(const std::string& name) {
  std::ifstream in(std::string(TOPOGRASP_HANDS_DATA) + "/" + name + "_fk_reference.json");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  return Json::parse(text.str());
}

int link_index(const auto& model, std::string_view name) {
  for (std::size_t i = 0; i < model.n_links; ++i)
    if (model.links[i].spec.name.view() == name) return static_cast<int>(i);
  return -1;
}

Eigen::Isometry3d pose_of(const Json& body) {
  const auto& p = body.at("pos").as_array();
  const auto& q = body.at("quat").as_array();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Vec3(p[0].as_number(), p[1].as_number(), p[2].as_number());
  T.linear() =
      Eigen::Quaterniond(q[0].as_number(), q[1].as_number(), q[2].as_number(), q[3].as_number())
          .normalized()
          .toRotationMatrix();
  return T;
}

// Every link of M that is a body of the reference, in the frame of the reference's body `root`,
// against M's forward kinematics at the reference's configurations.
template <const auto& M>
void check_against_reference(const std::string& file, std::string_view root) {
  const Json ref = read_reference(file);
  const auto& joints = ref.at("joint_bodies").as_array();
  KinematicsData<M> d;
  int compared = 0;
  for (const Json& config : ref.at("configs").as_array()) {
    const auto& qpos = config.at("qpos").as_array();
    Vec<M.nq> q = Vec<M.nq>::Zero();
    int set = 0;
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const int l = link_index(M, joints[j].as_string());
      // A joint of or above the imported root (the Shadow hand's wrist) is not in the model.
      if (l <= 0) continue;
      const Link& link = M.links[static_cast<std::size_t>(l)];
      INFO(file << ": joint of " << joints[j].as_string());
      REQUIRE(link.actuated);
      q[link.q] = qpos[j].as_number();
      ++set;
    }
    REQUIRE(set == M.nq);
    forward_kinematics(d, q);
    const auto& bodies = config.at("bodies");
    const Eigen::Isometry3d root_pose = pose_of(bodies.at(root));
    for (std::size_t i = 0; i < M.n_links; ++i) {
      const std::string name(M.links[i].spec.name.view());
      if (!bodies.contains(name)) continue;
      const Eigen::Isometry3d mj = root_pose.inverse() * pose_of(bodies.at(name));
      const Eigen::Isometry3d ours = link_pose(d, static_cast<int>(i));
      INFO(file << ": " << name);
      CHECK((mj.translation() - ours.translation()).norm() < 1e-12);
      CHECK((mj.linear() - ours.linear()).norm() < 1e-9);  // the reference's quaternions: 17 digits
      ++compared;
    }
  }
  CHECK(compared == 16 * static_cast<int>(M.n_links));
}

// Each joint that closes (closing != 0), moved in its closing direction from the middle of its
// range, brings its digit's tip nearer the point 6 cm in front of the palm centre, the others
// held at the middle of their ranges.
template <const auto& M>
void check_closing_directions() {
  KinematicsData<M> d;
  Vec<M.nq> mid;
  for (int i = 0; i < M.nq; ++i) mid[i] = 0.5 * (M.joint_spec(i).lower + M.joint_spec(i).upper);
  forward_kinematics(d, mid);
  const Eigen::Isometry3d palm = frame_pose(d, M.frame("palm_centre"));
  const Vec3 target = palm * Vec3(0, 0, 0.06);
  int closing = 0;
  for (std::size_t f = 0; f < M.n_fingers; ++f) {
    const Finger& finger = M.fingers[f];
    const LinkPoint& tip = finger.points[static_cast<std::size_t>(finger.size - 1)];
    for (int i = 0; i < M.nq; ++i) {
      const LinkSpec& s = M.joint_spec(i);
      if (s.closing == 0.0) continue;
      // Only the joints that move this finger's tip.
      bool moves = false;
      for (const SupportJoint& j : M.supports[static_cast<std::size_t>(tip.link)])
        moves = moves || j.q == i;
      if (!moves) continue;
      const auto tip_distance = [&](double dq) {
        Vec<M.nq> q = mid;
        q[i] += dq;
        forward_kinematics(d, q);
        return (link_pose(d, tip.link) * Vec3(tip.offset[0], tip.offset[1], tip.offset[2]) - target)
            .norm();
      };
      INFO(M.name.view() << ": joint " << s.name.view());
      CHECK(tip_distance(0.1 * s.closing) < tip_distance(0.0));
      ++closing;
    }
  }
  CHECK(closing >= 8);
}

template <const auto& M>
void check_actuators() {
  for (int i = 0; i < M.nq; ++i) {
    INFO(M.joint_spec(i).name.view());
    CHECK(M.joint_spec(i).effort > 0.0);
    CHECK(M.joint_spec(i).velocity > 0.0);
  }
}

}  // namespace

TEST_CASE("hands: the shipped hands have MuJoCo's kinematics of their source files") {
  check_against_reference<models::allegro_hand>("wonik_allegro", "palm");
  check_against_reference<models::leap_hand>("leap_hand", "palm");
  check_against_reference<models::shadow_hand>("shadow_hand", "rh_palm");
}

TEST_CASE("hands: the shipped hands close toward their palms") {
  check_closing_directions<models::allegro_hand>();
  check_closing_directions<models::leap_hand>();
  check_closing_directions<models::shadow_hand>();
}

TEST_CASE("hands: the shipped hands have a thumb, fingers and a motor on every joint") {
  STATIC_REQUIRE(models::allegro_hand.nq == 16);
  STATIC_REQUIRE(models::allegro_hand.n_fingers == 4);
  STATIC_REQUIRE(models::leap_hand.nq == 16);
  STATIC_REQUIRE(models::leap_hand.n_fingers == 4);
  STATIC_REQUIRE(models::shadow_hand.nq == 22);  // the wrist's two joints left out
  STATIC_REQUIRE(models::shadow_hand.n_fingers == 5);
  check_actuators<models::allegro_hand>();
  check_actuators<models::leap_hand>();
  check_actuators<models::shadow_hand>();
}

namespace {

// Checks that \p model is what its description file data/hands/<name>.json says: its name, palm
// centre, fingers and thumb, each joint's closing direction and motor, each frame.
template <const auto& M>
void check_description(const std::string& name) {
  std::ifstream in(std::string(TOPOGRASP_DATA_DIR) + "/hands/" + name + ".json");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  const Json doc = Json::parse(text.str());
  CHECK(M.name.view() == doc.at("name").as_string());
  CHECK(M.palm_name.view() == doc.at("palm_centre").as_string());
  const auto check_chain = [](const FingerSpec& f, const Json& chain) {
    CHECK(f.name.view() == chain.at("name").as_string());
    const auto& points = chain.at("points").as_array();
    for (std::size_t k = 0; k < points.size(); ++k)
      CHECK(f.chain[k].view() == points[k].as_string());
    if (points.size() < f.chain.size()) CHECK(f.chain[points.size()].view().empty());
  };
  const auto& fingers = doc.at("fingers").as_array();
  REQUIRE(M.n_fingers == fingers.size() + 1);
  std::size_t k = 0;
  for (std::size_t i = 0; i < M.n_fingers; ++i) {
    CAPTURE(i);
    check_chain(M.fingers[i].spec, static_cast<int>(i) == M.thumb ? doc.at("thumb") : fingers[k++]);
  }
  for (const auto& [joint, j] : doc.at("joints").as_object()) {
    CAPTURE(joint);
    const int l = link_index(M, joint);
    REQUIRE(l >= 0);
    const LinkSpec& spec = M.links[static_cast<std::size_t>(l)].spec;
    CHECK(spec.closing == j.at("closes").as_number());
    CHECK(spec.effort == j.at("effort").as_number());
    CHECK(spec.velocity == j.at("velocity").as_number());
  }
  for (const Json& f : doc.at("frames").as_array()) {
    const std::string frame = f.at("name").as_string();
    CAPTURE(frame);
    const int i = M.find_frame(frame);
    REQUIRE(i >= 0);
    const FrameSpec& spec = M.frames[static_cast<std::size_t>(i)].spec;
    CHECK(spec.link.view() == f.at("link").as_string());
    for (std::size_t c = 0; c < 3; ++c)
      CHECK(spec.offset.p[c] == f.at("position").as_array()[c].as_number());
    if (f.contains("xyaxes"))  // the frame's x and y axes: its rotation's first two columns
      for (std::size_t c = 0; c < 6; ++c)
        CHECK(spec.offset.R[3 * (c % 3) + c / 3] == f.at("xyaxes").as_array()[c].as_number());
  }
}

}  // namespace

TEST_CASE("hands: the shipped hands are what their description files say (data/hands)") {
  check_description<models::allegro_hand>("allegro_hand");
  check_description<models::leap_hand>("leap_hand");
  check_description<models::shadow_hand>("shadow_hand");
}
