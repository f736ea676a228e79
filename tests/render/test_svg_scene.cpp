// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <topograsp/model/models.hpp>
#include <topograsp/render/svg_panels.hpp>
#include <topograsp/render/svg_plot.hpp>
#include <topograsp/render/svg_scene.hpp>
#include <vector>

#include "support/text.hpp"

using namespace topograsp;

namespace {

using test::count;

struct Box2 {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
};

// The attribute points="..." of every element whose tag starts with tag (in document order).
std::vector<std::vector<std::pair<double, double>>> points_of(const std::string& svg,
                                                              const std::string& tag) {
  std::vector<std::vector<std::pair<double, double>>> out;
  for (std::size_t at = svg.find("<" + tag); at != std::string::npos;
       at = svg.find("<" + tag, at + 1)) {
    const std::size_t p = svg.find("points=\"", at) + 8;
    const std::size_t e = svg.find('"', p);
    std::vector<std::pair<double, double>> pts;
    const std::string list = svg.substr(p, e - p);
    std::size_t i = 0;
    while (i < list.size()) {
      std::size_t comma = list.find(',', i), space = list.find(' ', comma);
      if (space == std::string::npos) space = list.size();
      pts.emplace_back(std::stod(list.substr(i, comma - i)),
                       std::stod(list.substr(comma + 1, space - comma - 1)));
      i = space + 1;
    }
    out.push_back(pts);
  }
  return out;
}

Box2 bounds(const std::vector<std::vector<std::pair<double, double>>>& polys) {
  Box2 b;
  for (const auto& poly : polys)
    for (const auto& [x, y] : poly)
      b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x), b.y0 = std::min(b.y0, y),
      b.y1 = std::max(b.y1, y);
  return b;
}

Primitive cube(const Vec3& centre, double half) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = centre;
  return Primitive::box(T, Vec3::Constant(half));
}

// Looking straight down (-z) with +y up: +x is right, +y up in the image.
SvgCamera top_view() {
  SvgCamera c;
  c.direction = Vec3(0, 0, -1);
  c.up = Vec3::UnitY();
  c.width = 400;
  c.height = 400;
  c.margin = 20;
  c.max_edge = 1.0;  // no splitting of flat parts
  c.segments = 8;
  return c;
}

}  // namespace

TEST_CASE("a box seen along an axis is one face fitted into the image", "[render][svg_scene]") {
  SvgScene scene;
  scene.add(cube(Vec3(0.3, -0.2, 0.1), 0.1), Rgb{200, 100, 50}, "object");
  const std::string svg = scene.svg(top_view());
  CHECK(svg.rfind("<?xml", 0) == 0);
  CHECK(count(svg, "<svg ") == 1);
  CHECK(count(svg, "</svg>") == 1);
  CHECK(count(svg, "<polygon") == 1);
  CHECK(count(svg, "class=\"object\"") == 1);
  CHECK(count(svg, "<polyline") == 0);
  CHECK(count(svg, "<path") == 0);
  const Box2 b = bounds(points_of(svg, "polygon"));
  CHECK(b.x0 == Approx(20.0));
  CHECK(b.x1 == Approx(380.0));
  CHECK(b.y0 == Approx(20.0));
  CHECK(b.y1 == Approx(380.0));
  CHECK(scene.fit_zoom(top_view()) == Approx(1800.0));  // 360 px over 0.2 m

  SECTION("split faces tile the same square") {
    SvgCamera c = top_view();
    c.max_edge = 0.05;  // 0.2 m sides in 4 pieces
    const std::string split = scene.svg(c);
    CHECK(count(split, "<polygon") == 16);
    const Box2 s = bounds(points_of(split, "polygon"));
    CHECK(s.x0 == Approx(20.0));
    CHECK(s.x1 == Approx(380.0));
  }
  SECTION("a corner view shows three differently shaded faces") {
    SvgCamera c = top_view();
    c.direction = Vec3(-1, -1, -1);
    c.up = Vec3::UnitZ();
    const std::string corner = scene.svg(c);
    REQUIRE(count(corner, "<polygon") == 3);
    const std::regex fill("fill=\"(#[0-9a-f]{6})\"");
    std::vector<std::string> fills;
    for (auto it = std::sregex_iterator(corner.begin(), corner.end(), fill);
         it != std::sregex_iterator(); ++it)
      fills.push_back((*it)[1]);
    REQUIRE(fills.size() == 3);  // the background is "white"
    CHECK(fills[0] != fills[1]);
    CHECK(fills[1] != fills[2]);
    CHECK(fills[0] != fills[2]);
  }
}

TEST_CASE("round shapes seen along their axis show only the near end", "[render][svg_scene]") {
  const SvgCamera c = top_view();  // 8 segments around
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  SECTION("cylinder: the top cap, one fan of 8 triangles") {
    SvgScene scene;
    scene.add(Primitive::cylinder(T, 0.05, 0.2), svg_colours::object);
    const std::string svg = scene.svg(c);
    CHECK(count(svg, "<polygon") == 8);
    const Box2 b = bounds(points_of(svg, "polygon"));
    CHECK(b.x1 - b.x0 == Approx(360.0));  // the octagon fitted across
    CHECK(0.5 * (b.x0 + b.x1) == Approx(200.0));
  }
  SECTION("capsule: the top hemisphere, 8 triangles and 8 quads") {
    SvgScene scene;
    scene.add(Primitive::capsule(Vec3(0, 0, -0.1), Vec3(0, 0, 0.1), 0.05), svg_colours::skin);
    const std::string svg = scene.svg(c);
    CHECK(count(svg, "<polygon") == 16);
  }
  SECTION("sphere: about half of its 32 faces") {
    SvgScene scene;
    scene.add(Primitive::sphere(Vec3(1, 2, 3), 0.05), svg_colours::skin);
    SvgCamera oblique = c;
    oblique.direction = Vec3(0.3, -1, -0.2);
    oblique.up = Vec3::UnitZ();
    const std::string svg = scene.svg(oblique);
    const std::size_t n = count(svg, "<polygon");
    CHECK(n >= 12);
    CHECK(n <= 20);
    const Box2 b = bounds(points_of(svg, "polygon"));
    CHECK(std::max(b.x1 - b.x0, b.y1 - b.y0) == Approx(360.0));
  }
}

TEST_CASE("the painter's algorithm draws the nearer of two overlapping shapes last",
          "[render][svg_scene]") {
  for (const bool near_first : {false, true}) {
    SvgScene scene;
    const Primitive far = cube(Vec3(0, 0, 0), 0.1), near = cube(Vec3(0.05, 0.05, 0.3), 0.1);
    if (near_first) scene.add(near, Rgb{0, 0, 255}, "near");
    scene.add(far, Rgb{255, 0, 0}, "far");
    if (!near_first) scene.add(near, Rgb{0, 0, 255}, "near");
    const std::string svg = scene.svg(top_view());
    // Seen from above: only the tops, the near one (higher) over the far one.
    REQUIRE(count(svg, "<polygon") == 2);
    CHECK(svg.find("class=\"far\"") < svg.find("class=\"near\""));
    // The camera turned around: now the far cube's bottom is in front.
    SvgCamera below = top_view();
    below.direction = Vec3(0, 0, 1);
    const std::string from_below = scene.svg(below);
    REQUIRE(count(from_below, "<polygon") == 2);
    CHECK(from_below.find("class=\"near\"") < from_below.find("class=\"far\""));
  }
}

TEST_CASE("polylines and markers are drawn on top, at their projected points",
          "[render][svg_scene]") {
  SvgScene scene;
  scene.add(cube(Vec3::Zero(), 0.1), svg_colours::robot, "hand");
  scene.add_polyline({Vec3(0, 0, 0.5), Vec3(0.1, 0, 0.5), Vec3(0.1, 0.1, 0.5)}, Rgb{255, 0, 0},
                     "gamma");
  scene.add_polyline({Vec3(0, 0, 0), Vec3(-0.1, 0, 0)}, Rgb{0, 255, 0});  // no legend
  scene.add_marker(Vec3(0, 0, 0), "centre of mass");
  SvgCamera c = top_view();
  c.zoom = 1000.0;
  c.target = Vec3::Zero();
  const std::string svg = scene.svg(c);
  CHECK(count(svg, "<polygon") == 1);
  CHECK(count(svg, "<polyline") == 2);
  CHECK(count(svg, "<circle") == 2);  // the marker and its legend symbol
  CHECK(count(svg, "<path") == 2);
  CHECK(count(svg, "<line") == 1);  // the one labelled polyline in the legend
  CHECK(count(svg, ">gamma</text>") == 1);
  CHECK(count(svg, ">centre of mass</text>") == 1);
  CHECK(svg.rfind("<polygon") < svg.find("<polyline"));
  const auto lines = points_of(svg, "polyline");
  REQUIRE(lines.size() == 2);
  REQUIRE(lines[0].size() == 3);
  // The target at the centre (200, 200); +x to the right, +y up, 1000 px per metre.
  CHECK(lines[0][0].first == Approx(200.0));
  CHECK(lines[0][0].second == Approx(200.0));
  CHECK(lines[0][1].first == Approx(300.0));
  CHECK(lines[0][1].second == Approx(200.0));
  CHECK(lines[0][2].first == Approx(300.0));
  CHECK(lines[0][2].second == Approx(100.0));
  CHECK(svg.find("<circle cx=\"200.00\" cy=\"200.00\"") != std::string::npos);
}

TEST_CASE("scene output is deterministic with fixed number formatting", "[render][svg_scene]") {
  constexpr auto& hand = models::human_hand;
  KinematicsData<hand> d;
  Vec<hand.nq> q = Vec<hand.nq>::Constant(0.3);
  forward_kinematics(d, q);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Vec3(0.1, 0.0, 0.05);
  SvgScene scene;
  scene.add_model(d, svg_colours::skin, "hand", T);
  scene.add_hand_curves(d, T);
  scene.add(Primitive::sphere(Vec3(0.1, 0.0, 0.2), 0.03), svg_colours::object, "object");
  scene.add_marker(Vec3(0.1, 0.0, 0.2), "centre of mass");
  scene.set_title("a hand").set_caption("line one\nline two");
  CHECK(scene.shape_count() == hand.n_shapes + 1);
  REQUIRE(scene.polylines().size() == hand_curve_count<hand>);
  CHECK(scene.polylines()[0].label ==
        "\xCE\xB3"
        "1 (index)");
  const SvgCamera c;
  const std::string a = scene.svg(c), b = scene.svg(c), copied = SvgScene(scene).svg(c);
  CHECK(a == b);
  CHECK(a == copied);
  CHECK(count(a, "<polyline") == 4);
  CHECK(count(a, ">a hand</text>") == 1);
  CHECK(count(a, ">line one</text>") == 1);
  CHECK(count(a, ">line two</text>") == 1);
  CHECK(count(a, "<polygon") > 100);
  // Every coordinate has two decimals and the drawing stays inside the image.
  const std::regex number_pair("(-?[0-9]+\\.[0-9][0-9]),(-?[0-9]+\\.[0-9][0-9])");
  const std::regex any_pair("([-0-9.e+]+),([-0-9.e+]+)");
  const auto polys = points_of(a, "polygon");
  for (const auto& poly : polys) CHECK(poly.size() >= 3);
  const Box2 box = bounds(polys);
  CHECK(box.x0 >= c.margin - 1e-9);
  CHECK(box.x1 <= c.width - c.margin + 1e-9);
  CHECK(box.y0 >= c.margin + 24 - 1e-9);             // under the title
  CHECK(box.y1 <= c.height - c.margin - 32 + 1e-9);  // over the two caption lines
  const std::size_t pairs =
      std::distance(std::sregex_iterator(a.begin(), a.end(), any_pair), std::sregex_iterator());
  const std::size_t fixed =
      std::distance(std::sregex_iterator(a.begin(), a.end(), number_pair), std::sregex_iterator());
  CHECK(pairs == fixed);
  CHECK(a.find("-0.00") == std::string::npos);
}

TEST_CASE("an empty scene renders an empty but valid SVG", "[render][svg_scene]") {
  const SvgScene scene;
  CHECK(scene.empty());
  CHECK(scene.fit_zoom(SvgCamera{}) == 0.0);
  const std::string svg = scene.svg();
  CHECK(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0) == 0);
  CHECK(svg.size() > 20);
  CHECK(svg.substr(svg.size() - 7) == "</svg>\n");
  CHECK(count(svg, "<polygon") == 0);
  CHECK(count(svg, "<polyline") == 0);
  CHECK(count(svg, "<text") == 0);
  const std::vector<SvgPanel> none;
  const std::string panels = svg_panels(none);
  CHECK(count(panels, "<svg") == 1);
  CHECK(count(panels, "</svg>") == 1);
}

TEST_CASE("side-by-side panels share one scale and carry their captions", "[render][svg_scene]") {
  SvgScene big, small;
  big.add(cube(Vec3::Zero(), 0.1), svg_colours::skin, "hand");
  small.add(cube(Vec3::Zero(), 0.05), svg_colours::robot, "hand");
  const SvgCamera c = top_view();
  const std::vector<SvgPanel> panels{{big, c, "human grasp\nstable", Rgb{0, 128, 0}},
                                     {small, c, "topological\nunstable", Rgb{200, 0, 0}}};
  const std::string svg = svg_panels(panels, "hammer, grasp 3");
  CHECK(count(svg, "<svg") == 3);                         // the document and two panels
  CHECK(svg.find("width=\"812\"") != std::string::npos);  // 400 + 12 + 400
  CHECK(count(svg, ">hammer, grasp 3</text>") == 1);
  CHECK(count(svg, ">human grasp</text>") == 1);
  CHECK(count(svg, "fill=\"#c80000\">unstable</text>") == 1);
  CHECK(count(svg, "fill=\"#008000\">stable</text>") == 1);
  const auto polys = points_of(svg, "polygon");
  REQUIRE(polys.size() == 2);
  const Box2 a = bounds({polys[0]}), b = bounds({polys[1]});
  CHECK(b.x1 - b.x0 == Approx(0.5 * (a.x1 - a.x0)));  // the same scale: half the size
  CHECK(a.x1 - a.x0 == Approx(360.0));
  const std::string own = svg_panels(panels, "", false);
  const auto own_polys = points_of(own, "polygon");
  REQUIRE(own_polys.size() == 2);
  const Box2 ob = bounds({own_polys[1]});
  CHECK(ob.x1 - ob.x0 == Approx(360.0));  // each fitted on its own
}

TEST_CASE("bad scene input throws naming the argument", "[render][svg_scene]") {
  SvgScene scene;
  const auto throws_naming = [](auto&& f, const std::string& name) {
    try {
      f();
      FAIL("no exception for " << name);
    } catch (const topograsp::invalid_argument& e) {
      CHECK(std::string(e.what()).rfind(name + ":", 0) == 0);
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Primitive bad = cube(Vec3::Zero(), 0.1);
  bad.p.x() = nan;
  throws_naming([&] { scene.add(bad, Rgb{}); }, "shape");
  const std::vector<Primitive> list{cube(Vec3::Zero(), 0.1), bad};
  throws_naming([&] { scene.add(list, Rgb{}); }, "shapes");
  CHECK(scene.shape_count() == 0);  // nothing added from a bad list
  Primitive flat = cube(Vec3::Zero(), 0.1);
  flat.size.z() = 0.0;
  throws_naming([&] { scene.add(flat, Rgb{}); }, "shape");
  throws_naming([&] { scene.add_polyline({Vec3(0, 0, nan)}, Rgb{}); }, "points");
  throws_naming([&] { scene.add_marker(Vec3(nan, 0, 0)); }, "position");
  constexpr auto& sdh = models::schunk_sdh;
  KinematicsData<sdh> d;
  forward_kinematics(d, Vec<sdh.nq>::Zero());
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = nan;
  throws_naming([&] { scene.add_model(d, Rgb{}, "hand", T); }, "T_world_base");
  throws_naming([&] { scene.add_hand_curves(d, T); }, "T_world_base");
  forward_kinematics(d, Vec<sdh.nq>::Constant(nan));
  throws_naming([&] { scene.add_model(d, Rgb{}); }, "d");

  scene.add(cube(Vec3::Zero(), 0.1), Rgb{});
  SvgCamera c;
  c.direction = Vec3::Zero();
  throws_naming([&] { (void)scene.svg(c); }, "camera.direction");
  c = SvgCamera{};
  c.up = c.direction;
  throws_naming([&] { (void)scene.svg(c); }, "camera.up");
  c = SvgCamera{};
  c.zoom = -1;
  throws_naming([&] { (void)scene.svg(c); }, "camera.zoom");
  c = SvgCamera{};
  c.width = 0;
  throws_naming([&] { (void)scene.svg(c); }, "camera.width");
  c = SvgCamera{};
  c.target = Vec3(nan, 0, 0);
  throws_naming([&] { (void)scene.svg(c); }, "camera.target");
  c = SvgCamera{};
  c.segments = 2;
  throws_naming([&] { (void)scene.svg(c); }, "camera.segments");
  throws_naming([&] { scene.write("/nonexistent-dir/x.svg"); }, "path");
}

TEST_CASE("the winding plot draws a line per curve and dashed targets", "[render][svg_plot]") {
  std::vector<Vec2> w, y;
  for (int t = 0; t <= 10; ++t) {
    w.emplace_back(0.1 * t, 0.05 * t);
    y.emplace_back(1.0, 0.5);
  }
  const std::string svg = winding_plot<2>(w, y, "Fig. 7").str();
  CHECK(count(svg, "<polyline") == 4);
  CHECK(count(svg, "stroke-dasharray=\"6 4\" points=") == 2);
  CHECK(count(svg,
              ">w(\xCE\xB3"
              "1)</text>") == 1);
  CHECK(count(svg,
              ">target y(\xCE\xB3"
              "2)</text>") == 1);
  CHECK(count(svg, ">Fig. 7</text>") == 1);
  // gamma_1 and its target share the first colour of the palette, as in SvgScene.
  CHECK(count(svg, "stroke=\"#1f77b4\" stroke-width=\"2.50\" points=") == 1);
  CHECK(count(svg, "stroke=\"#1f77b4\" stroke-width=\"1.50\" stroke-dasharray=\"6 4\" points=") ==
        1);
  CHECK(SvgScene::hex(svg_colours::curve(0)) == SvgLinePlot::series_colour(0));
  CHECK(SvgScene::hex(svg_colours::curve(1)) == SvgLinePlot::series_colour(1));
  const auto lines = points_of(svg, "polyline");
  CHECK(lines[0].size() == 11);
  CHECK(lines[0].front().second > lines[0].back().second);  // rising values go up
  CHECK(count(winding_plot<2>(w).str(), "<polyline") == 2);
  CHECK_THROWS_AS(winding_plot<2>(w, std::vector<Vec2>(3)), topograsp::invalid_argument);
  CHECK_THROWS_AS(winding_plot<2>(w, {}, "t", "x", {"only one"}), topograsp::invalid_argument);
  CHECK(count(winding_plot<2>({}).str(), "<polyline") == 0);
}

TEST_CASE("the cost plot marks every sweep and switches to a log axis", "[render][svg_plot]") {
  std::vector<AicoSweepRecord> sweeps(4);
  const double costs[] = {5000.0, 40.0, 60.0, 2.0};
  for (std::size_t k = 0; k < 4; ++k) {
    sweeps[k].cost = costs[k];
    sweeps[k].accepted = k != 2;
  }
  const SvgLinePlot plot = cost_plot(sweeps);
  CHECK(plot.log_y());
  const std::string svg = plot.str();
  CHECK(count(svg, "<polyline") == 1);
  CHECK(count(svg, "<circle") == 4 + 3 + 2);   // every sweep, the accepted ones, the legend
  CHECK(count(svg, "font-size=\"9\">") >= 4);  // decades 10^0 .. 10^4 as superscripts
  const auto line = points_of(svg, "polyline")[0];
  // log axis: 5000 -> 40 drops more than 60 -> 2 rises, by log ratio
  const double d01 = line[1].second - line[0].second, d23 = line[3].second - line[2].second;
  CHECK(d01 / d23 == Approx(std::log10(5000.0 / 40.0) / std::log10(60.0 / 2.0)).epsilon(0.02));
  sweeps[0].cost = 3.0;
  CHECK_FALSE(cost_plot(sweeps).log_y());  // within a factor of 100
  sweeps[1].cost = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(cost_plot(sweeps), topograsp::invalid_argument);
  SvgLinePlot negative;
  negative.add_series("s", {0, 1}, {-1, 1});
  CHECK_THROWS_AS(negative.set_log_y(), topograsp::invalid_argument);
}
