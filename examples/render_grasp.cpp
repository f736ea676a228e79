// SPDX-License-Identifier: BSD-3-Clause
// Renders the human hand and the Schunk SDH holding the hammer to SVG: each hand alone (with its
// hand curves and the hammer's centre of mass), both side by side, the windings of the curves
// while the fingers close (as in the paper's Fig. 7), and an index.html page that shows them.
//
// The grasps are kinematic: each hand is placed over the handle, moved along its approach until
// it touches, then every closing joint turns in small steps until the links after it touch the
// hammer (the distal joints keep curling after the proximal ones stop).
//
//   render_grasp [--out DIR] [--view X,Y,Z]   (the camera's view direction, world frame)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/grasp/hand_axes.hpp>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/object.hpp>
#include <topograsp/grasp/placement.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/render/html_page.hpp>
#include <topograsp/render/svg_panels.hpp>
#include <topograsp/render/svg_plot.hpp>
#include <topograsp/render/svg_scene.hpp>
#include <topograsp/task/winding_task.hpp>

namespace {

using namespace topograsp;

// A kinematic grasp of a fixed-base hand model M: the palm pose in the object frame, the joints,
// and the windings of every hand curve around the centre of mass at each closing step.
template <const auto& M>
struct KinematicGrasp {
  Eigen::Isometry3d T_object_hand = Eigen::Isometry3d::Identity();
  Vec<M.nq> q = Vec<M.nq>::Zero();
  std::vector<Vec<hand_curve_count<M>>> windings;
};

// True if link l is \p ancestor or lies after it in the tree.
template <const auto& M>
bool in_subtree(int l, int ancestor) {
  for (; l >= 0; l = M.links[static_cast<std::size_t>(l)].parent)
    if (l == ancestor) return true;
  return false;
}

// The smallest distance between the shapes on links after (and on) link \p from and the object.
template <const auto& M>
double subtree_distance(const KinematicsData<M>& d, int from, const Composite& object) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < M.n_shapes; ++i) {
    if (!in_subtree<M>(M.shapes[i].link, from)) continue;
    const Primitive s = world_shape(d, i);
    for (const Primitive& part : object.parts())
      best = std::min(best, signed_distance(s, part).distance);
  }
  return best;
}

// Places the hand (its free-base twin Free) with the frame "grasp_centre" at \p centre, its axes
// along \p approach and \p up, backs it off, approaches until contact and closes every closing
// joint until the links after it touch the object (gap 1 mm).
template <const auto& M, const auto& Free>
KinematicGrasp<M> grasp(const GraspObject& object, const HandAxes& axes, const Vec3& centre,
                        const Vec3& approach, const Vec3& up, const Vec<M.nq>& pre) {
  const Composite shape = object.composite();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = palm_rotation(axes, approach, up);
  T.translation() = centre - 0.12 * approach;
  const Vec<Free.nq> start = place_frame<Free>(T, Free.frame("grasp_centre"), pre);
  const auto touched = approach_until_contact<Free>(start, approach, shape, 0.002, 0.3);
  KinematicGrasp<M> g;
  KinematicsData<Free> df;
  forward_kinematics(df, touched ? *touched : start);
  g.T_object_hand = link_pose(df, Free.link("palm"));
  // Close, in the hand frame.
  const Composite local = object.composite(g.T_object_hand.inverse());
  const WindingTask<M> winding(g.T_object_hand.inverse() * object.centre_of_mass());
  KinematicsData<M> d;
  g.q = pre;
  std::vector<bool> stopped(static_cast<std::size_t>(M.nq), false);
  const double step = 0.02;  // rad
  for (int k = 0; k < 200; ++k) {
    forward_kinematics(d, g.q);
    g.windings.push_back(winding.value(d));
    bool moved = false;
    for (int j = 0; j < M.nq; ++j) {
      const LinkSpec& spec = M.joint_spec(j);
      if (spec.closing == 0.0 || stopped[static_cast<std::size_t>(j)]) continue;
      const double before = g.q[j];
      g.q[j] = std::clamp(before + spec.closing * step, spec.lower, spec.upper);
      forward_kinematics(d, g.q);
      const int link = M.q_link[static_cast<std::size_t>(j)];
      if (g.q[j] == before || subtree_distance(d, link, local) < 0.001) {
        g.q[j] = before;
        stopped[static_cast<std::size_t>(j)] = true;
      } else {
        moved = true;
      }
    }
    if (!moved) break;
  }
  forward_kinematics(d, g.q);
  g.windings.push_back(winding.value(d));
  return g;
}

// A scene: the hammer (wooden handle, steel head), the hand, its curves and the centre of mass.
template <const auto& M>
SvgScene scene_of(const GraspObject& hammer, const KinematicGrasp<M>& g, Rgb hand_colour) {
  SvgScene scene;
  const Composite c = hammer.composite();
  scene.add(c.parts()[0], svg_colours::wood, "object");
  scene.add(c.parts()[1], svg_colours::steel, "object");
  KinematicsData<M> d;
  forward_kinematics(d, g.q);
  scene.add_model(d, hand_colour, "hand", g.T_object_hand);
  scene.add_hand_curves(d, g.T_object_hand);
  scene.add_marker(hammer.centre_of_mass(), "centre of mass");
  return scene;
}

std::string windings_text(const auto& w) {
  std::string s = "w =";
  for (int i = 0; i < w.size(); ++i) {
    char b[32];
    std::snprintf(b, sizeof b, " %.2f", w[i]);
    s += b;
  }
  return s;
}

template <const auto& M>
SvgLinePlot closing_plot(const KinematicGrasp<M>& g, const std::string& hand) {
  return winding_plot(g.windings, {}, "Windings while the " + hand + " closes", "closing step");
}

int usage(const char* argv0, int status) {
  std::fprintf(status == 0 ? stdout : stderr,
               "usage: %s [--out DIR] [--view X,Y,Z]\n"
               "Renders the human hand and the Schunk SDH holding the hammer to SVG files.\n",
               argv0);
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = "render-out";
  // The default view: from the handle's free end, to the side of the fingers, a little above.
  Vec3 view(0.75, 0.8, -0.45);
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") return usage(argv[0], 0);
    if (a == "--out" && i + 1 < argc)
      out = argv[++i];
    else if (a == "--view" && i + 1 < argc &&
             std::sscanf(argv[i + 1], "%lf,%lf,%lf", &view[0], &view[1], &view[2]) == 3)
      ++i;
    else
      return usage(argv[0], 2);
  }
  try {
    std::filesystem::create_directories(out);
    const GraspObject hammer = objects::hammer();
    // The handle runs along x (head at +x). Both hands come from above (-z): the human palm
    // with the fingers along -y, so that the handle lies across the palm, thumb toward the head;
    // the SDH with its thumb and fingers on either side of the handle.
    constexpr auto& human = models::human_hand;
    const Vec<20> pre = human_preshape();  // the demonstrations' pre-shape, thumb opposed
    const auto h = grasp<human, models::human_hand_free>(
        hammer, human_hand_axes, Vec3(-0.05, 0.0, 0.0), Vec3(0, 0, -1), Vec3(0, -1, 0), pre);
    constexpr auto& sdh = models::schunk_sdh;
    Vec<sdh.nq> sdh_pre = Vec<sdh.nq>::Zero();  // fingers spread open around the handle
    for (const char* j : {"finger_12", "finger_22", "thumb_2"}) sdh_pre[sdh.find_joint(j)] = -0.6;
    const auto s = grasp<sdh, models::schunk_sdh_free>(
        hammer, gripper_hand_axes, Vec3(-0.05, 0.0, 0.0), Vec3(0, 0, -1), Vec3(0, 1, 0), sdh_pre);

    const SvgScene human_scene = scene_of(hammer, h, svg_colours::skin);
    const SvgScene sdh_scene = scene_of(hammer, s, svg_colours::robot);
    SvgCamera camera;
    camera.direction = view;
    camera.width = 560;
    camera.height = 440;
    SvgScene titled = human_scene;
    titled.set_title("Human hand holding the hammer");
    titled.write(out + "/human_hammer.svg", camera);
    titled = sdh_scene;
    titled.set_title("Schunk SDH holding the hammer");
    titled.write(out + "/sdh_hammer.svg", camera);

    const std::vector<SvgPanel> panels{
        {human_scene, camera, "human hand\n" + windings_text(h.windings.back()), {}},
        {sdh_scene, camera, "Schunk SDH\n" + windings_text(s.windings.back()), {}}};
    write_svg(out + "/side_by_side.svg", svg_panels(panels, "The hammer, two hands"));
    closing_plot(h, "human hand").write(out + "/human_windings.svg");
    closing_plot(s, "SDH").write(out + "/sdh_windings.svg");

    HtmlPage page;
    page.title = "render_grasp: the hammer in two hands";
    page.intro =
        "Kinematic grasps of the hammer: each hand approaches from above and closes "
        "until its links touch. The curves are the hand curves, the black-and-white "
        "disc the centre of mass.";
    page.header = {"hand", "joints", "closing steps", "final windings"};
    page.rows = {{"human hand", std::to_string(human.nq), std::to_string(h.windings.size() - 1),
                  windings_text(h.windings.back())},
                 {"Schunk SDH", std::to_string(sdh.nq), std::to_string(s.windings.size() - 1),
                  windings_text(s.windings.back())}};
    page.figures = {{"side_by_side.svg", "Both hands side by side, at the same scale."},
                    {"human_windings.svg", "Windings of the human hand's curves while it closes."},
                    {"sdh_windings.svg", "Windings of the SDH's curves while it closes."}};
    write_html_page(out + "/index.html", page);
    std::printf("human hand: %zu closing steps, final %s\n", h.windings.size() - 1,
                windings_text(h.windings.back()).c_str());
    std::printf("Schunk SDH: %zu closing steps, final %s\n", s.windings.size() - 1,
                windings_text(s.windings.back()).c_str());
    std::printf(
        "wrote %s/{human_hammer,sdh_hammer,side_by_side,human_windings,sdh_windings}.svg "
        "and %s/index.html\n",
        out.c_str(), out.c_str());
    return 0;
  } catch (const topograsp::invalid_argument& e) {
    std::fprintf(stderr, "render_grasp: %s\n", e.what());
    return 2;
  }
}
