// SPDX-License-Identifier: BSD-3-Clause
// Hands from URDF and MJCF (io/hand_import.hpp): the made-up three-finger hand of tests/hands/data,
// imported at build time by topograsp_import_hand() into constexpr models, has MuJoCo's own
// kinematics of the same file (sites, geoms, bodies; 20 random configurations); what the import
// reads (classes, units, couplings, actuators, approximations); and each refusal names the file,
// the line, the element and the problem.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <utility>

#include <catch2/catch.hpp>
#include <topograsp/io/hand_import.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/model/model.hpp>

#include "support/random.hpp"
#include "support/throws.hpp"
#include "three_finger_described.hpp"  // the URDF hand with three_finger.json
#include "three_finger_mjcf.hpp"       // made by topograsp_import_hand() (tests/CMakeLists.txt)
#include "three_finger_urdf.hpp"

#ifdef TOPOGRASP_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

using namespace topograsp;

namespace {

const std::string data_dir = TOPOGRASP_HANDS_DATA;

// The hand descriptions: what the files cannot say, in the files' names.
namespace th = topograsp::test_hands;
constexpr auto mjcf_hand = make_model(
    "three_finger_mjcf",
    with_closing(th::mjcf::links, {{"index_base", 1},
                                   {"index_mid", 1},
                                   {"index_dist", 1},
                                   {"middle_base", 1},
                                   {"middle_mid", 1},
                                   {"thumb_dist", 1}}),
    th::mjcf::shapes, th::mjcf::frames,
    hand("palm_centre", finger("index", {"index_abd", "index_mid", "index_dist", "index_tip"}),
         finger("middle", {"middle_base", "middle_mid", "middle_dist", "middle_tip"}),
         thumb("thumb", {"thumb_base", "thumb_dist", "thumb_tip"})));

constexpr auto urdf_hand = make_model(
    "three_finger_urdf", with_closing(th::urdf::links, {{"index_mid", 1}, {"thumb_dist", 1}}),
    th::urdf::shapes,
    join(th::urdf::frames, frames(frame("palm_centre", "palm", at(0, 0, 0.03)),
                                  frame("thumb_tip", "thumb_dist", at(0, 0, 0.035)))),
    hand("palm_centre", finger("index", {"index_base", "index_mid", "index_dist", "index_tip"}),
         thumb("thumb", {"thumb_base", "thumb_dist", "thumb_tip"})));

// 16 MJCF joints' worth of checks need the link of a joint by the file's name.
const LinkSpec& link_named(const ImportedHand& h, std::string_view name) {
  for (const LinkSpec& l : h.links)
    if (l.name.view() == name) return l;
  FAIL("no link " << name);
  return h.links.front();
}

bool has_note(const ImportedHand& h, std::string_view fragment) {
  for (const std::string& n : h.notes)
    if (n.find(fragment) != std::string::npos) return true;
  return false;
}

// The message of the import_error (or xml_error) that importing \p text throws.
std::string import_failure(const std::string& text, const ImportOptions& options = {}) {
  try {
    (void)import_hand(parse_xml(text, "hand.xml"), options);
  } catch (const invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("hands: an MJCF hand is read with its classes, units, couplings and actuators") {
  const ImportedHand h = import_hand_file(data_dir + "/three_finger.xml");
  CHECK(h.format == HandFileFormat::mjcf);
  // Links: the root, then depth first; a body with two joints gives two links, the first named
  // after its joint.
  REQUIRE(h.links.size() == 11);
  CHECK(h.links[0].name.view() == "palm");
  CHECK(h.links[0].parent.empty());
  CHECK(h.links[1].name.view() == "index_abd");
  CHECK(h.links[2].name.view() == "index_base");
  CHECK(h.links[2].parent.view() == "index_abd");
  CHECK(h.joint_names[2] == "index_mcp");
  // Degrees to radians; ranges and axes from the classes (knuckle inside finger).
  const LinkSpec& abd = link_named(h, "index_abd");
  CHECK(abd.axis == std::array<double, 3>{1, 0, 0});
  CHECK(abd.lower == Approx(-20 * pi / 180));
  CHECK(abd.upper == Approx(20 * pi / 180));
  CHECK(abd.armature == 0.001);
  CHECK(link_named(h, "middle_dist").upper == Approx(80 * pi / 180));
  CHECK(link_named(h, "thumb_base").lower == Approx(-30 * pi / 180));
  // The joint away from its body's origin: index_mcp at z = 5 mm of index_base's body frame.
  CHECK(link_named(h, "index_base").origin.p[2] == Approx(0.005));
  // Actuators: a class's force range, a gear, a fixed tendon's coefficients.
  CHECK(abd.effort == Approx(0.5));
  CHECK(link_named(h, "index_base").effort == Approx(0.8));
  CHECK(link_named(h, "index_mid").effort == Approx(1.0));
  CHECK(link_named(h, "index_dist").effort == Approx(0.8));
  CHECK(link_named(h, "thumb_base").effort == Approx(0.8));
  CHECK(link_named(h, "thumb_dist").effort == 0.0);  // its motor has no force range
  CHECK(has_note(h, "a_thumb_slide has no force range"));
  // The coupling: middle_dip = 0.05 + 0.7 middle_pip, without an actuator of its own.
  const LinkSpec& dip = link_named(h, "middle_dist");
  CHECK(dip.mimic.view() == "middle_mid");
  CHECK(dip.multiplier == 0.7);
  CHECK(dip.offset == 0.05);
  CHECK(dip.armature == 0.0);
  // Geoms: the visual one left out, the ellipsoid a capsule; sites are frames.
  CHECK(h.shapes.size() == 10);
  CHECK(has_note(h, "ellipsoid"));
  REQUIRE(h.frames.size() == 5);
  CHECK(h.frames[0].name.view() == "palm_centre");
  // The root body's pose in the world is dropped.
  CHECK(h.links[0].origin == Pose{});
  CHECK(link_named(h, "palm").mass == 0.4);
}

TEST_CASE("hands: the header made at build time holds what the import reads") {
  for (const bool urdf : {false, true}) {
    const ImportedHand h =
        import_hand_file(data_dir + (urdf ? "/three_finger.urdf" : "/three_finger.xml"));
    const auto& links = urdf
                            ? std::vector<LinkSpec>(th::urdf::links.begin(), th::urdf::links.end())
                            : std::vector<LinkSpec>(th::mjcf::links.begin(), th::mjcf::links.end());
    REQUIRE(links.size() == h.links.size());
    for (std::size_t i = 0; i < links.size(); ++i) {
      INFO(h.links[i].name.view());
      CHECK(links[i].name == h.links[i].name);
      CHECK(links[i].parent == h.links[i].parent);
      CHECK(links[i].type == h.links[i].type);
      CHECK(links[i].lower == h.links[i].lower);  // shortest round-trip numbers: exact
      CHECK(links[i].effort == h.links[i].effort);
      CHECK(links[i].mimic == h.links[i].mimic);
      CHECK(links[i].origin.isometry().isApprox(h.links[i].origin.isometry(), 1e-14));
    }
  }
}

TEST_CASE("hands: a URDF hand is read with its joints, mimic and collisions") {
  const ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  CHECK(h.format == HandFileFormat::urdf);
  REQUIRE(h.links.size() == 8);
  CHECK(h.links[0].name.view() == "base");
  CHECK(link_named(h, "palm").type == JointType::fixed);
  const LinkSpec& abd = link_named(h, "index_base");
  CHECK(abd.effort == 0.5);
  CHECK(abd.velocity == 2.0);
  const LinkSpec& dip = link_named(h, "index_dist");
  CHECK(dip.mimic.view() == "index_mid");
  CHECK(dip.multiplier == 0.8);
  CHECK(dip.offset == 0.05);
  CHECK(dip.effort == 0.0);  // driven through its source
  CHECK(has_note(h, "mimic joint index_dip"));
  CHECK(link_named(h, "thumb_base").lower == Approx(-pi));  // continuous
  CHECK(has_note(h, "continuous joint thumb_rot"));
  CHECK(link_named(h, "thumb_dist").type == JointType::prismatic);
  // Collisions: box (full sizes halved), cylinders, a sphere and the mesh's bounding box.
  REQUIRE(h.shapes.size() == 7);
  CHECK(h.shapes[0].size == std::array<double, 3>{0.04, 0.015, 0.035});
  const ShapeSpec& mesh = h.shapes[2];
  CHECK(mesh.type == ShapeType::box);
  CHECK(mesh.size[0] == Approx(0.01));
  CHECK(mesh.size[1] == Approx(0.005));
  CHECK(mesh.size[2] == Approx(0.005));    // scaled by 2 along z
  CHECK(mesh.pose.p[0] == Approx(0.011));  // the origin plus the box's centre
  CHECK(mesh.pose.p[2] == Approx(0.005 + 0.006));
  CHECK(has_note(h, "bounding box"));
}

TEST_CASE("hands: imported models are constexpr models with their hand descriptions") {
  STATIC_REQUIRE(mjcf_hand.nq == 9);  // 10 joints, middle_dip coupled
  STATIC_REQUIRE(urdf_hand.nq == 4);  // 5 joints, index_dip mimics index_pip
  STATIC_REQUIRE(mjcf_hand.n_fingers == 3);
  STATIC_REQUIRE(urdf_hand.joint_spec(1).closing == 1.0);
  KinematicsData<mjcf_hand> d;
  forward_kinematics(d, Vec<mjcf_hand.nq>::Zero());
  // The index tip, straight: along the chain of the file.
  CHECK(d.frame_p[mjcf_hand.frame("index_tip")].allFinite());
}

#ifdef TOPOGRASP_HAVE_MUJOCO
namespace {

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};

std::unique_ptr<mjModel, MjModelDeleter> load(const std::string& path) {
  char error[1000] = "";
  std::unique_ptr<mjModel, MjModelDeleter> m(mj_loadXML(path.c_str(), nullptr, error, 1000));
  INFO(error);
  REQUIRE(m);
  return m;
}

// Sets MuJoCo's joints from q of model M (a mimic joint from its source) and runs its kinematics.
template <const auto& M>
void set_mujoco(const mjModel* m, mjData* md, const ImportedHand& h, const Vec<M.nq>& q) {
  for (std::size_t i = 0; i < h.links.size(); ++i) {
    if (h.joint_names[i].empty() || M.links[i].spec.type == JointType::fixed) continue;
    const int j = mj_name2id(m, mjOBJ_JOINT, h.joint_names[i].c_str());
    REQUIRE(j >= 0);
    const Link& l = M.links[i];
    md->qpos[m->jnt_qposadr[j]] = l.actuated ? q[l.q] : l.spec.multiplier * q[l.q] + l.spec.offset;
  }
  mj_kinematics(m, md);
}

// MuJoCo's pose of the body \p name relative to the root body \p root.
Eigen::Isometry3d body_in_root(const mjModel* m, const mjData* d, const char* name,
                               const char* root) {
  const auto pose = [&](int b) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.translation() = Vec3(d->xpos[3 * b], d->xpos[3 * b + 1], d->xpos[3 * b + 2]);
    T.linear() = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(d->xmat + 9 * b);
    return T;
  };
  const int b = mj_name2id(m, mjOBJ_BODY, name), r = mj_name2id(m, mjOBJ_BODY, root);
  REQUIRE(b >= 0);
  REQUIRE(r >= 0);
  return pose(r).inverse() * pose(b);
}

}  // namespace

TEST_CASE("hands: the imported MJCF hand has MuJoCo's kinematics of the same file") {
  const ImportedHand h = import_hand_file(data_dir + "/three_finger.xml");
  const auto m = load(data_dir + "/three_finger.xml");
  std::unique_ptr<mjData, MjDataDeleter> md(mj_makeData(m.get()));
  std::mt19937_64 rng(7);
  KinematicsData<mjcf_hand> d;
  for (int trial = 0; trial < 20; ++trial) {
    const auto q = test::random_configuration<mjcf_hand>(rng);
    forward_kinematics(d, q);
    set_mujoco<mjcf_hand>(m.get(), md.get(), h, q);
    const int root = mj_name2id(m.get(), mjOBJ_BODY, "palm");
    const Vec3 p0(md->xpos[3 * root], md->xpos[3 * root + 1], md->xpos[3 * root + 2]);
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> R0(md->xmat + 9 * root);
    // Every site, and every collision geom's centre and axis, in the root's frame.
    for (std::size_t f = 0; f < mjcf_hand.n_frames; ++f) {
      const std::string site(mjcf_hand.frames[f].spec.name.view());
      const int s = mj_name2id(m.get(), mjOBJ_SITE, site.c_str());
      REQUIRE(s >= 0);
      const Vec3 ps(md->site_xpos[3 * s], md->site_xpos[3 * s + 1], md->site_xpos[3 * s + 2]);
      CHECK((R0.transpose() * (ps - p0) - d.frame_p[f]).norm() < 1e-12);
    }
    int shape = 0;
    for (int g = 0; g < m->ngeom; ++g) {
      if (m->geom_contype[g] == 0 && m->geom_conaffinity[g] == 0) continue;
      const Vec3 pg(md->geom_xpos[3 * g], md->geom_xpos[3 * g + 1], md->geom_xpos[3 * g + 2]);
      const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> Rg(md->geom_xmat +
                                                                              9 * g);
      const Eigen::Isometry3d ours =
          link_pose(d, mjcf_hand.shapes[shape].link) *
          mjcf_hand.shapes[static_cast<std::size_t>(shape)].spec.pose.isometry();
      INFO("geom " << g);
      CHECK((R0.transpose() * (pg - p0) - ours.translation()).norm() < 1e-12);
      // The axis of capsules and cylinders up to its sign (MuJoCo's fromto runs it the other way);
      // ours of the ellipsoid is the capsule along its longest axis.
      if (m->geom_type[g] != mjGEOM_ELLIPSOID)
        CHECK(std::abs((R0.transpose() * Rg.col(2)).dot(ours.linear().col(2))) > 1.0 - 1e-12);
      ++shape;
    }
    CHECK(shape == static_cast<int>(mjcf_hand.n_shapes));
  }
}

TEST_CASE("hands: the imported URDF hand has MuJoCo's kinematics of the same file") {
  const ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  const auto m = load(data_dir + "/three_finger.urdf");
  std::unique_ptr<mjData, MjDataDeleter> md(mj_makeData(m.get()));
  std::mt19937_64 rng(8);
  KinematicsData<urdf_hand> d;
  for (int trial = 0; trial < 20; ++trial) {
    const auto q = test::random_configuration<urdf_hand>(rng);
    forward_kinematics(d, q);
    set_mujoco<urdf_hand>(m.get(), md.get(), h, q);
    // Every link MuJoCo keeps as a body (it fuses links on fixed joints into their parents).
    int compared = 0;
    for (std::size_t i = 1; i < urdf_hand.n_links; ++i) {
      const std::string name(urdf_hand.links[i].spec.name.view());
      if (mj_name2id(m.get(), mjOBJ_BODY, name.c_str()) < 0) continue;
      const Eigen::Isometry3d mj = body_in_root(m.get(), md.get(), name.c_str(), "base");
      const Eigen::Isometry3d ours = link_pose(d, static_cast<int>(i));
      INFO(name);
      CHECK((mj.translation() - ours.translation()).norm() < 1e-12);
      CHECK((mj.linear() - ours.linear()).norm() < 1e-12);
      ++compared;
    }
    CHECK(compared >= 5);
  }
}
#endif

TEST_CASE("hands: a file that cannot be imported is refused, naming the file, line and element") {
  const auto refused = [](const std::string& text, const std::string& fragment,
                          const ImportOptions& options = {}) {
    const std::string why = import_failure(text, options);
    INFO(why);
    CHECK(why.rfind("hand.xml:", 0) == 0);
    CHECK(why.find(fragment) != std::string::npos);
  };
  const std::string urdf_head = "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n";
  refused(urdf_head +
              "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child "
              "link=\"b\"/></joint></robot>",
          "hand.xml:4: <joint name=\"j\">: revolute joint without <limit>");
  refused(urdf_head +
              "<joint name=\"j\" type=\"floating\"><parent link=\"a\"/><child "
              "link=\"b\"/></joint></robot>",
          "joint type \"floating\" is not supported");
  refused(urdf_head +
              "<joint name=\"j\" type=\"fixed\"><parent link=\"c\"/><child "
              "link=\"b\"/></joint></robot>",
          "parent link \"c\" is not in the file");
  refused(urdf_head + "</robot>", "more than one root link (a, b)");
  refused(urdf_head +
              "<joint name=\"j\" type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/>"
              "</joint><joint name=\"k\" type=\"fixed\"><parent link=\"b\"/><child "
              "link=\"a\"/></joint></robot>",
          "no link is the root");
  refused("<robot><link name=\"a_name_that_is_much_longer_than_31\"/></robot>",
          "longer than 31 characters");
  refused(urdf_head +
              "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
              "<limit lower=\"1\" upper=\"0\"/></joint></robot>",
          "lower limit above upper limit");
  refused(urdf_head +
              "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
              "<axis xyz=\"0 0\"/><limit lower=\"0\" upper=\"1\"/></joint></robot>",
          "xyz=\"0 0\" has 2 numbers, expected 3");
  refused(urdf_head +
              "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
              "<limit lower=\"0\" upper=\"x\"/><mimic joint=\"z\"/></joint></robot>",
          "upper=\"x\" is not a list of finite numbers");
  refused(urdf_head +
              "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>"
              "<limit lower=\"0\" upper=\"1\"/><mimic joint=\"z\"/></joint></robot>",
          "mimics \"z\", which is not a joint below the root");
  refused(
      "<robot><link name=\"a\"><collision><geometry><mesh filename=\"gone.stl\"/>"
      "</geometry></collision></link></robot>",
      "cannot read the mesh");
  {
    ImportOptions skip;
    skip.skip_missing_meshes = true;
    const ImportedHand h = import_hand(
        parse_xml("<robot><link name=\"a\"><collision><geometry><mesh filename=\"gone.stl\"/>"
                  "</geometry></collision></link></robot>",
                  "hand.xml"),
        skip);
    CHECK(h.shapes.empty());
    CHECK(has_note(h, "could not be read and was left out"));
  }
  ImportOptions root_c;
  root_c.root = "c";
  refused(urdf_head + "</robot>", "no link called \"c\"", root_c);
  // MJCF.
  const auto mjcf = [](const std::string& body) {
    return "<mujoco>\n<worldbody>\n<body name=\"palm\">\n" + body +
           "\n</body>\n</worldbody>\n</mujoco>";
  };
  refused(mjcf("<body name=\"f\"><joint name=\"j\" type=\"ball\"/></body>"),
          "hand.xml:4: <joint name=\"j\">: joint type \"ball\" is not supported");
  refused(mjcf("<body name=\"f\"><joint name=\"j\" class=\"nope\"/></body>"),
          "no default class called \"nope\"");
  refused(mjcf("<body name=\"f\" euler=\"1 2\"><joint name=\"j\"/></body>"),
          "euler=\"1 2\" has 2 numbers, expected 3");
  refused(mjcf("<body name=\"f\" euler=\"1 2 3\" quat=\"1 0 0 0\"/>"),
          "more than one orientation given");
  refused(mjcf("<body name=\"f\"><joint name=\"j\" type=\"slide\"/></body>"),
          "a slide joint without a range");
  refused(mjcf("<body name=\"f\"><freejoint/></body>"), "a free joint below the root");
  refused(mjcf("<body><geom size=\"0.1\"/></body>"), "a body without a name");
  refused(mjcf("<geom type=\"box\" size=\"0.1 0.1\"/>"), "a box geom needs 3 size numbers");
  refused(mjcf("<geom type=\"mesh\" mesh=\"m\"/>"), "no mesh asset called \"m\"");
  refused("<mujoco><include file=\"x.xml\"/></mujoco>", "<include> is not supported");
  refused("<mujoco><compiler angle=\"grad\"/><worldbody/></mujoco>", "angle=\"grad\"");
  refused("<mujoco/>", "no <worldbody>");
  refused("<mujoco><worldbody><body name=\"a\"/><body name=\"b\"/></worldbody></mujoco>",
          "more than one top-level body (a, b): choose one with --root");
  refused(
      "<mujoco><worldbody><body name=\"a\"><body name=\"b\"><joint name=\"j\"/></body>"
      "</body></worldbody><equality><joint joint1=\"j\" joint2=\"j\" polycoef=\"0 1 1 0 "
      "0\"/></equality></mujoco>",
      "only linear couplings");
  refused(
      "<mujoco><worldbody><body name=\"a\"/></worldbody><equality><joint joint1=\"x\"/>"
      "</equality></mujoco>",
      "needs joint1= and joint2=");
  refused("<scene/>", "neither a URDF file (<robot>) nor an MJCF file (<mujoco>)");
  // What make_model() would refuse, refused at import with the file and the name.
  refused(mjcf("<body name=\"palm\"/>"), "hand.xml: link \"palm\": a second link or frame");
  refused(mjcf("<site name=\"palm\"/>"), "hand.xml: frame \"palm\": a second link or frame");
  refused(
      "<mujoco><worldbody><body name=\"a\"><body name=\"b\"><joint name=\"j\" "
      "range=\"0 1\"/><body name=\"c\"><joint name=\"k\" range=\"0 1\"/><body "
      "name=\"d\"><joint name=\"l\" range=\"0 1\"/></body></body></body></body>"
      "</worldbody><equality><joint joint1=\"k\" joint2=\"j\"/><joint joint1=\"l\" "
      "joint2=\"k\"/></equality></mujoco>",
      "joint of link \"d\": it is coupled to a joint that is fixed or itself coupled");
  refused("<robot><link name=\"a\"><inertial><mass value=\"1e300\"/></inertial></link></robot>",
          "link \"a\": its origin, mass or centre of mass is not finite or beyond 1e6");
  refused(
      "<robot><link name=\"a\"><collision><geometry><box size=\"1 0 1\"/></geometry>"
      "</collision></link></robot>",
      "hand.xml:1: <box>: its size must be > 0");
  refused(mjcf("<body name=\"f\"><joint name=\"j\" range=\"0 1e308\"/></body>"),
          "joint of link \"f\": its limits are not finite or lower is above upper");
  // A root below the top: the body's subtree, its own pose and joint dropped.
  ImportOptions root_f;
  root_f.root = "f";
  const ImportedHand cut = import_hand(
      parse_xml(mjcf("<body name=\"f\" pos=\"1 0 0\"><joint name=\"i\"/><body name=\"g\"><joint "
                     "name=\"j\" range=\"0 1\"/></body></body>"),
                "hand.xml"),
      root_f);
  REQUIRE(cut.links.size() == 2);
  CHECK(has_note(cut, "the joint i of the root body f is left out"));
  CHECK(cut.links[0].name.view() == "f");
  CHECK(cut.links[0].origin == Pose{});
  CHECK(cut.links[1].upper == Approx(pi / 180));  // degrees, MJCF's default unit
  // Not well-formed XML, and a file that is not there.
  CHECK(import_failure("<robot><link name=\"a\"></robot>").rfind("hand.xml:1:", 0) == 0);
  CHECK_THROWS_AS(import_hand_file(data_dir + "/not_there.urdf"), xml_error);
}

TEST_CASE("hands: model_header refuses a namespace that is not one") {
  const ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  for (const char* bad : {"", "1abc", "a:b", "a::", "::a", "a b", "a::1b"})
    test::check_throws_naming([&] { (void)model_header(h, bad); }, "ns");
  const std::string header = model_header(h, "my::hands");
  CHECK(header.find("namespace my::hands {") != std::string::npos);
  CHECK(header.find("// Note: the mimic joint index_dip") != std::string::npos);
  CHECK(header.find("revolute(\"index_base\", \"palm\", ") != std::string::npos);
}

TEST_CASE("hands: the import follows MuJoCo's and ROS's rules in the corners") {
  const auto import_text = [](const std::string& text, const ImportOptions& options = {}) {
    return import_hand(parse_xml(text, "hand.xml"), options);
  };
  // A childclass above the chosen root still applies below it.
  ImportOptions hand_root;
  hand_root.root = "hand";
  const ImportedHand cut = import_text(
      "<mujoco><default><default class=\"c\"><joint axis=\"1 0 0\" range=\"-0.5 0.5\"/>"
      "</default></default><worldbody><body name=\"arm\" childclass=\"c\"><body name=\"hand\">"
      "<body name=\"f\"><joint name=\"j\"/></body></body></body></worldbody></mujoco>",
      hand_root);
  REQUIRE(cut.links.size() == 2);
  CHECK(cut.links[1].axis == std::array<double, 3>{1, 0, 0});
  CHECK(cut.links[1].upper == Approx(0.5 * pi / 180));  // degrees: MJCF's default unit
  // Two top-level <default> elements add up.
  const ImportedHand two = import_text(
      "<mujoco><compiler angle=\"radian\"/><default><joint range=\"-0.5 0.5\"/></default>"
      "<default><geom density=\"500\"/></default><worldbody><body name=\"a\"><body name=\"b\">"
      "<joint name=\"j\"/><geom type=\"box\" size=\"0.1 0.1 0.1\"/></body></body></worldbody>"
      "</mujoco>");
  CHECK(two.links[1].upper == 0.5);
  CHECK(two.links[1].mass == Approx(500 * 0.008));
  // autolimits="false": a range limits only a joint marked limited="true".
  const ImportedHand unlimited = import_text(
      "<mujoco><compiler angle=\"radian\" autolimits=\"false\"/><worldbody><body name=\"a\">"
      "<body name=\"b\"><joint name=\"j\" range=\"0 1\"/></body><body name=\"c\"><joint "
      "name=\"k\" range=\"0 1\" limited=\"true\"/></body></body></worldbody></mujoco>");
  CHECK(unlimited.links[1].upper == Approx(pi));
  CHECK(unlimited.links[2].upper == 1.0);
  // Geoms outside inertiagrouprange weigh nothing; two actuators on a joint add up.
  const ImportedHand weighed = import_text(
      "<mujoco><compiler angle=\"radian\" inertiagrouprange=\"0 2\"/><worldbody><body "
      "name=\"a\"><body name=\"b\"><joint name=\"j\" range=\"0 1\"/><geom type=\"box\" "
      "size=\"0.1 0.1 0.1\" mass=\"1\"/><geom type=\"box\" size=\"0.1 0.1 0.1\" mass=\"2\" "
      "group=\"3\"/></body></body></worldbody><actuator><motor joint=\"j\" forcerange=\"-1 "
      "1\"/><motor joint=\"j\" forcerange=\"-2 2\"/></actuator></mujoco>");
  CHECK(weighed.links[1].mass == 1.0);
  CHECK(weighed.links[1].effort == 3.0);
  // A tiny size is written exactly, not as 0.
  const ImportedHand tiny = import_text(
      "<mujoco><worldbody><body name=\"a\"><geom size=\"1e-16\"/></body></worldbody></mujoco>");
  CHECK(model_header(tiny, "t").find("1e-16") != std::string::npos);
  // What MuJoCo splices in or MuJoCo 3 adds, and names that would break the C++, are refused.
  const auto refused = [&](const std::string& text, const std::string& fragment) {
    std::string why = "(no error)";
    try {
      (void)import_text(text);
    } catch (const invalid_argument& e) {
      why = e.what();
    }
    INFO(why);
    CHECK(why.find(fragment) != std::string::npos);
  };
  refused(
      "<mujoco><worldbody><body name=\"a\"><include file=\"f.xml\"/></body></worldbody>"
      "</mujoco>",
      "<include> is not supported");
  refused("<mujoco><worldbody><body name=\"a\"><frame/></body></worldbody></mujoco>",
          "<frame> (MuJoCo 3) is not supported");
  refused("<robot><link name=\"a&quot;b\"/></robot>", "has a quote, a backslash");
  refused(
      "<robot><link name=\"a\"/><link name=\"b\"/><joint name=\"j&#10;#error\" "
      "type=\"fixed\"><parent link=\"a\"/><child link=\"b\"/></joint></robot>",
      "control character");
  for (const char* keyword : {"int", "a::class", "std"})
    test::check_throws_naming([&] { (void)model_header(tiny, keyword); }, "ns");
}

TEST_CASE("hands: package:// meshes are found in ROS's package layout") {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / "topograsp_package_test";
  fs::remove_all(root);
  fs::create_directories(root / "my_hand" / "urdf");
  fs::create_directories(root / "my_hand" / "meshes");
  fs::copy_file(data_dir + "/meshes/box.stl", root / "my_hand" / "meshes" / "box.stl");
  {
    std::ofstream urdf(root / "my_hand" / "urdf" / "hand.urdf");
    urdf << "<robot name=\"r\"><link name=\"a\"><collision><geometry><mesh "
            "filename=\"package://my_hand/meshes/box.stl\"/></geometry></collision></link>"
            "</robot>";
  }
  const ImportedHand h = import_hand_file((root / "my_hand" / "urdf" / "hand.urdf").string());
  REQUIRE(h.shapes.size() == 1);
  CHECK(h.shapes[0].size[0] == Approx(0.01));
  fs::remove_all(root);
}

TEST_CASE("hands: a link that no chain of joints from the root reaches is refused") {
  const auto urdf = [](const std::string& joints) {
    return "<robot name=\"r\">\n<link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>"
           "<link name=\"d\"/><link name=\"e\"/>\n<joint name=\"ab\" type=\"fixed\"><parent "
           "link=\"a\"/><child link=\"b\"/></joint>" +
           joints + "</robot>";
  };
  const auto fixed = [](const char* parent, const char* child) {
    return std::string("<joint name=\"") + parent + child + "\" type=\"fixed\"><parent link=\"" +
           parent + "\"/><child link=\"" + child + "\"/></joint>";
  };
  // c and d joined to each other beside the tree a - b, e below them.
  const std::string cycle = urdf(fixed("c", "d") + fixed("d", "c") + fixed("d", "e"));
  const std::string why = import_failure(cycle);
  CHECK(why ==
        "hand.xml:1: <robot name=\"r\">: links not reached from the root \"a\": c (part of a "
        "cycle of joints), d (part of a cycle of joints), e (below a cycle of joints)");
  // With --root, a cycle is refused still; links above the root are the arm cut off.
  ImportOptions root_b;
  root_b.root = "b";
  CHECK(import_failure(cycle, root_b).find("root \"b\": c (part of a cycle of joints)") !=
        std::string::npos);
  const ImportedHand cut = import_hand(
      parse_xml(urdf(fixed("b", "c") + fixed("c", "d") + fixed("a", "e")), "hand.xml"), root_b);
  REQUIRE(cut.links.size() == 3);
  CHECK(cut.links[0].name.view() == "b");
  // Without a cycle every link is imported, from URDF and MJCF alike (MJCF is nested: a tree).
  CHECK(
      import_hand(parse_xml(urdf(fixed("b", "c") + fixed("c", "d") + fixed("a", "e")), "hand.xml"))
          .links.size() == 5);
  CHECK(import_hand(parse_xml("<mujoco><worldbody><body name=\"a\"><body name=\"b\"/><body "
                              "name=\"c\"><body name=\"d\"/></body></body></worldbody></mujoco>",
                              "hand.xml"))
            .links.size() == 4);
}

TEST_CASE("hands: a mesh with a vertex that is not finite is refused, naming the file and vertex") {
  const auto failure = [](const std::string& path) {
    try {
      (void)import_hand_file(path);
    } catch (const import_error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string refused_dir = data_dir + "/refused";
  const std::string why = failure(refused_dir + "/nan_vertex.urdf");
  INFO(why);
  CHECK(why.rfind(refused_dir + "/nan_vertex.urdf:6: <mesh>: the mesh \"" + refused_dir +
                      "/nan_vertex.obj\" has a vertex that is not finite (vertex 2,",
                  0) == 0);
  // MJCF: a mesh geom, colliding or only weighed, and an infinite vertex.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "topograsp_nan_mesh_test";
  fs::create_directories(dir);
  std::ofstream(dir / "inf.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 inf\nf 1 2 3\nf 1 2 4\n";
  for (const char* contype : {"", " contype=\"0\" conaffinity=\"0\""}) {
    std::ofstream(dir / "hand.xml")
        << "<mujoco><asset><mesh name=\"m\" file=\"inf.obj\"/></asset><worldbody><body "
           "name=\"a\"><geom type=\"mesh\" mesh=\"m\""
        << contype << "/></body></worldbody></mujoco>";
    const std::string mjcf_why = failure((dir / "hand.xml").string());
    INFO(mjcf_why);
    CHECK(mjcf_why.find("inf.obj\" has a vertex that is not finite (vertex 3,") !=
          std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("hands: text from the user or the file cannot break the generated header") {
  using detail::header_text;
  using detail::HeaderText;
  // Control characters escaped (octal), or refused where asked; quotes and backslashes escaped in
  // string literals; a backslash that would end a comment's line written \134.
  CHECK(header_text("a\r\nb\x7f", HeaderText::comment) == "a\\015\\012b\\177");
  CHECK(header_text("a\"b\\c\t", HeaderText::string) == "a\\\"b\\\\c\\011");
  CHECK(header_text("dir\\x\\", HeaderText::comment) == "dir\\x\\134");
  CHECK(header_text("a */ b", HeaderText::comment) == "a */ b");  // the header has // comments
  test::check_throws_naming([] { (void)header_text("a\rb", HeaderText::comment, "comments"); },
                            "comments");
  ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  test::check_throws_naming([&] { (void)model_header(h, "h", {"fine", "a\rb"}); }, "comments");
  // A file name with a line break and a note with a carriage return and a trailing backslash:
  // each stays on its comment line.
  h.source = "/tmp/hand\n#error broken\r.urdf";
  h.notes.push_back("a note\r#error broken\\");
  const std::string header = model_header(h, "h", {"a comment ending in \\"});
  CHECK(header.find("from hand\\012#error broken\\015.urdf (urdf)") != std::string::npos);
  CHECK(header.find("// Note: a note\\015#error broken\\134\n") != std::string::npos);
  CHECK(header.find("// a comment ending in \\134\n") != std::string::npos);
  CHECK(header.find('\r') == std::string::npos);
  // Every line that starts with # is one the writer means.
  std::size_t lines = 0;
  for (std::size_t at = 0; (at = header.find('\n', at)) != std::string::npos; ++at, ++lines) {
    const bool meant = header.compare(at + 1, 1, "#") != 0 ||
                       header.compare(at + 1, 7, "#pragma") == 0 ||
                       header.compare(at + 1, 8, "#include") == 0;
    CHECK(meant);
  }
  CHECK(lines > 10);
}

namespace {

// The message of the import_error that describing the URDF hand with \p text throws.
std::string description_failure(const std::string& text) {
  ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  try {
    (void)describe_hand(h, Json::parse(text), "hand.json");
  } catch (const import_error& e) {
    return e.what();
  }
  return "(no error)";
}

// A description of the URDF hand with \p extra fields (JSON members, each followed by a comma).
std::string described(const std::string& extra) {
  return "{" + extra +
         R"("name": "h", "palm_centre": "palm", "fingers": [{"name": "index", "points": )"
         R"(["index_base", "index_tip"]}], "thumb": {"name": "thumb", "points": ["thumb_base", )"
         R"("thumb_dist"]}})";
}

}  // namespace

TEST_CASE("hands: a description file makes the model that C++ lines make") {
  // three_finger.json says what urdf_hand's C++ lines say: the same model, built at build time.
  constexpr auto& model = th::described::model;
  STATIC_REQUIRE(model.nq == urdf_hand.nq);
  STATIC_REQUIRE(model.n_fingers == urdf_hand.n_fingers);
  STATIC_REQUIRE(model.name.view() == "three_finger_urdf");
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    CAPTURE(i);
    CHECK(model.links[i].spec == urdf_hand.links[i].spec);
  }
  REQUIRE(model.frames.size() == urdf_hand.frames.size());
  KinematicsData<model> d;
  KinematicsData<urdf_hand> e;
  const Vec<model.nq> q = Vec<model.nq>::Constant(0.2);
  forward_kinematics(d, q);
  forward_kinematics(e, Vec<urdf_hand.nq>(q));
  for (int i = 0; i < static_cast<int>(model.links.size()); ++i)
    CHECK((link_pose(d, i).matrix() - link_pose(e, i).matrix()).norm() < 1e-15);
  for (const char* f : {"palm_centre", "thumb_tip"}) {  // the frames the description adds
    CAPTURE(f);
    const int i = model.find_frame(f);
    REQUIRE(i >= 0);
    CHECK((frame_pose(d, i).matrix() - frame_pose(e, urdf_hand.find_frame(f)).matrix()).norm() <
          1e-15);
  }
  // The header says what the description did, and what the file lacks.
  ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  CHECK(has_note(h, "the link index_mid has no <inertial>: it is massless"));
  const HandDescription desc = describe_hand_file(h, data_dir + "/three_finger.json");
  CHECK(desc.fingers.size() == 1);
  const std::string header = model_header(h, "a", {}, &desc);
  CHECK_THAT(header, Catch::Contains("inline constexpr auto model = make_model(") &&
                         Catch::Contains(".closes(1") &&
                         Catch::Contains("#include <topograsp/model/model.hpp>"));
}

TEST_CASE("hands: a description holds joints still, fills motors and gives links mass") {
  ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  const ImportedHand before = h;
  const LinkSpec rot = link_named(h, "thumb_base");  // the continuous joint thumb_rot, about z
  (void)describe_hand(
      h,
      Json::parse(described(R"("joints": {"thumb_rot": {"hold": 0.3}, "index_abd": {"closes": -1, )"
                            R"("effort": 0.7}}, "defaults": {"velocity": 4, "density": 1000}, )")),
      "hand.json");
  // Held: a fixed joint whose origin is the joint's frame turned by 0.3 rad, noted.
  const LinkSpec& held = link_named(h, "thumb_base");
  CHECK(held.type == JointType::fixed);
  const Eigen::Isometry3d expected =
      rot.origin.isometry() * Eigen::AngleAxisd(0.3, Vec3(rot.axis[0], rot.axis[1], rot.axis[2]));
  CHECK((held.origin.isometry().matrix() - expected.matrix()).norm() < 1e-12);
  CHECK(has_note(h, "the joint thumb_base is held at 0.3 by the description (hand.json)"));
  // A joint named by the file's name closes and gets its motor; the defaults fill the rest.
  const LinkSpec& abd = link_named(h, "index_base");
  CHECK(abd.closing == -1.0);
  CHECK(abd.effort == 0.7);
  CHECK(abd.velocity == 2.0);                         // the file's
  CHECK(link_named(h, "index_mid").velocity == 3.0);  // the file's
  ImportedHand unheld = import_hand_file(data_dir + "/three_finger.urdf");
  (void)describe_hand(unheld, Json::parse(described(R"("defaults": {"velocity": 4}, )")),
                      "hand.json");
  CHECK(link_named(unheld, "thumb_base").velocity == 4.0);  // the file gives none
  CHECK(link_named(unheld, "index_mid").velocity == 3.0);
  CHECK(link_named(unheld, "index_dist").velocity == 0.0);  // mimic: driven by its source
  // A link without mass gets its collision shapes' at the density, noted; the others keep theirs.
  const LinkSpec& mid = link_named(h, "index_mid");
  CHECK(link_named(before, "index_mid").mass == 0.0);
  double volume = 0.0;
  for (const ShapeSpec& sh : h.shapes)
    if (sh.link == mid.name) volume += shape_mass_properties(sh, 1.0).mass;
  CHECK(volume > 0.0);
  CHECK(mid.mass == Approx(1000.0 * volume));
  CHECK(has_note(h, "the link index_mid has no mass in three_finger.urdf"));
  CHECK(link_named(h, "palm").mass == link_named(before, "palm").mass);
}

TEST_CASE("hands: a description's frame turned by its axes (xyaxes) is written exactly") {
  ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  const HandDescription desc = describe_hand(
      h,
      Json::parse(described(R"("frames": [{"name": "c", "link": "palm", "position": [0, 0, 0.01], )"
                            R"("xyaxes": [0, 1, 0, 1, 0, 0]}, {"name": "d", "link": "palm", )"
                            R"("xyaxes": [2, 0, 0, 1, 1, 0]}, {"name": "e", "link": "palm", )"
                            R"("xyaxes": [1, 1, 0, 0, 0, 3]}], )")),
      "hand.json");
  REQUIRE(h.frames.size() >= 3);
  const auto frame_named = [&](std::string_view n) {
    return *std::find_if(h.frames.begin(), h.frames.end(),
                         [&](const FrameSpec& f) { return f.name.view() == n; });
  };
  // x onto y, y onto x: z onto -z; every entry exact.
  CHECK(frame_named("c").offset.R == std::array<double, 9>{0, 1, 0, 1, 0, 0, 0, 0, -1});
  // The y axis is made square to x, both of unit length.
  CHECK(frame_named("d").offset.R == std::array<double, 9>{1, 0, 0, 0, 1, 0, 0, 0, 1});
  const Mat3 e = frame_named("e").offset.rotation();
  CHECK((e.col(0) - Vec3(1, 1, 0).normalized()).norm() < 1e-15);
  CHECK((e.col(2) - Vec3(1, -1, 0).normalized()).norm() < 1e-15);
  CHECK((e.transpose() * e - Mat3::Identity()).norm() < 1e-15);
  // The header writes a turn that takes axes onto axes as its matrix (a quaternion would bring
  // 1/sqrt(2) and inexact zeros), any other as a quaternion.
  const std::string header = model_header(h, "a", {}, &desc);
  CHECK_THAT(header,
             Catch::Contains(
                 R"(frame("c", "palm", Pose{{0, 1, 0, 1, 0, 0, 0, 0, -1}, {0.0, 0.0, 0.01}}))") &&
                 Catch::Contains(R"(frame("e", "palm", at(0.0, 0.0, 0.0).quat()"));
}

TEST_CASE("hands: a description that does not fit its hand file says where and what to write") {
  CHECK(description_failure(described("")) == "(no error)");
  CHECK_THAT(description_failure(described(R"("fingerz": [], )")),
             Catch::StartsWith("hand.json: fingerz: unknown key (known: name, palm_centre, "));
  CHECK_THAT(
      description_failure(R"({"name": "h", "palm_centre": "palm", "fingers": [{"name": "i", )"
                          R"("points": ["index_base", "index_tipp"]}], "thumb": {"name": "t", )"
                          R"("points": ["thumb_base", "thumb_dist"]}})"),
      Catch::StartsWith("hand.json: fingers[0].points[1]: \"index_tipp\" is no link or frame of "
                        "three_finger.urdf (links: base, palm, index_base,"));
  CHECK_THAT(description_failure(R"({"name": "h", "palm_centre": "palm", "fingers": [{"name": )"
                                 R"("i", "points": ["index_base", "index_tip"]}]})"),
             Catch::StartsWith("hand.json: thumb: missing: a hand needs a thumb"));
  CHECK_THAT(description_failure(R"({"name": "h", "palm_centre": "palm", "thumb": {"name": "t", )"
                                 R"("points": ["thumb_base", "thumb_dist"]}})"),
             Catch::StartsWith("hand.json: fingers: expected a list of at least one finger"));
  CHECK_THAT(description_failure(R"({"name": "h", "palm_centre": "centre", "fingers": [{"name": )"
                                 R"("i", "points": ["index_base", "index_tip"]}], "thumb": )"
                                 R"({"name": "t", "points": ["thumb_base", "thumb_dist"]}})"),
             Catch::StartsWith("hand.json: palm_centre: \"centre\" is no link or frame of "
                               "three_finger.urdf (add it under \"frames\""));
  // Each field that does not fit the URDF hand, and the start of what the refusal says.
  const std::pair<const char*, const char*> cases[] = {
      {R"("joints": {"palm_mount": {"closes": 1}}, )",
       "hand.json: joints.palm_mount: \"palm_mount\" is a fixed joint in three_finger.urdf: only "
       "a moving joint closes"},
      {R"("joints": {"wrist": {"closes": 1}}, )",
       "hand.json: joints.wrist: no joint or link \"wrist\" in three_finger.urdf (links: "},
      {R"("joints": {"index_abd": {"closes": 0.5}}, )",
       "hand.json: joints.index_abd.closes: expected 1 (increasing closes), -1 (decreasing "
       "closes) or 0"},
      {R"("joints": {"thumb_slide": {"hold": 0.5}}, )",
       "hand.json: joints.thumb_slide.hold: expected a number from 0 to 0.01"},
      {R"("joints": {"index_pip": {"hold": 0.1}}, )",
       "hand.json: joints.index_pip.hold: the joint \"index_dist\" follows it (a mimic joint)"},
      {R"("joints": {"index_abd": {"hold": 0, "closes": 1}}, )",
       "hand.json: joints.index_abd: a held joint does not close and has no motor"},
      {R"("frames": [{"name": "tip", "link": "nolink"}], )",
       "hand.json: frames[0].link: no link \"nolink\" in three_finger.urdf"},
      {R"("frames": [{"name": "palm", "link": "palm"}], )",
       "hand.json: frames[0].name: \"palm\" is already a frame or link"},
      {R"("frames": [{"name": "c", "link": "palm", "rpy": [0, 1]}], )",
       "hand.json: frames[0].rpy: expected 3 numbers"},
      {R"("defaults": {"density": -1}, )",
       "hand.json: defaults.density: expected a number from 1 to"},
      {R"("frames": [{"name": "c", "link": "palm", "rpy": [0, 0, 0], "xyaxes": [1, 0, 0, 0, 1, )"
       R"(0]}], )",
       "hand.json: frames[0]: give the rotation one way: \"rpy\", \"quaternion\" or \"xyaxes\""},
      {R"("frames": [{"name": "c", "link": "palm", "xyaxes": [1, 0, 0, -2, 0, 0]}], )",
       "hand.json: frames[0].xyaxes: expected two axes that are not zero nor parallel"},
      {R"("frames": [{"name": "c", "link": "palm", "xyaxes": [0, 0, 0, 0, 1, 0]}], )",
       "hand.json: frames[0].xyaxes: expected two axes that are not zero nor parallel"},
      {R"("frames": [{"name": "c", "link": "palm", "xyaxes": [1, 0, 0]}], )",
       "hand.json: frames[0].xyaxes: expected 6 numbers"},
  };
  for (const auto& [field, message] : cases) {
    CAPTURE(field);
    CHECK_THAT(description_failure(described(field)), Catch::StartsWith(message));
  }
  CHECK_THAT(description_failure("[1]"), Catch::StartsWith("hand.json: expected a JSON object"));
  // With the description's text, the message names the line of the field too.
  {
    const std::string text =
        "{\n  \"name\": \"h\",\n  \"palm_centre\": \"palm\",\n"
        "  \"fingers\": [\n    {\"name\": \"index\",\n"
        "     \"points\": [\"index_base\",\n                \"index_tipp\"]}]\n}";
    ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
    CHECK_THROWS_WITH(describe_hand(h, Json::parse(text), "hand.json", text),
                      Catch::StartsWith("hand.json:7: fingers[0].points[1]: \"index_tipp\" is no "
                                        "link or frame of "));
    ImportedHand g = import_hand_file(data_dir + "/three_finger.urdf");
    const std::string no_thumb =
        "{\n  \"name\": \"h\",\n  \"palm_centre\": \"palm\",\n"
        "  \"fingers\": [{\"name\": \"index\", \"points\": "
        "[\"index_base\", \"index_tip\"]}]\n}";
    CHECK_THROWS_WITH(describe_hand(g, Json::parse(no_thumb), "hand.json", no_thumb),
                      Catch::StartsWith("hand.json:1: thumb: missing"));
  }
  ImportedHand h = import_hand_file(data_dir + "/three_finger.urdf");
  CHECK_THROWS_WITH(describe_hand_file(h, data_dir + "/no_such.json"),
                    Catch::EndsWith("no_such.json: cannot be opened"));
  CHECK_THROWS_WITH(describe_hand_file(h, data_dir + "/three_finger.urdf"),
                    Catch::Contains("three_finger.urdf: not JSON: "));
}
