// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The pictures of a grasp-transfer run (grasp_transfer --figures): for a few grasps per object
/// the human grasp and its transfer by each method side by side with the stability suite's verdicts
/// (the paper's Fig. 5 and 6), the windings of one plan over time (Fig. 7) with AICO's cost per
/// sweep, and index.html with Table I and every figure.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/file_name.hpp>
#include <topograsp/render/html_page.hpp>
#include <topograsp/render/svg_panels.hpp>
#include <topograsp/render/svg_plot.hpp>
#include <topograsp/render/svg_scene.hpp>

namespace topograsp {

/// The rows of Table I for \p results: hypotheses, stable demonstrations, and the success rate of
/// each method, one column per object.
template <const auto& M>
[[nodiscard]] std::vector<std::vector<std::string>> table_rows(
    const std::vector<ObjectResultOf<M>>& results) {
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> hyp{"hypotheses"}, stable{"stable demonstrations"};
  for (const ObjectResultOf<M>& r : results) {
    hyp.push_back(std::to_string(r.hypotheses));
    stable.push_back(std::to_string(r.stable_human()));
  }
  rows.push_back(hyp);
  rows.push_back(stable);
  if (results.empty()) return rows;
  for (std::size_t m = 0; m < results.front().methods.size(); ++m) {
    std::vector<std::string> row{std::string(to_string(results.front().methods[m].method))};
    for (const ObjectResultOf<M>& r : results) {
      const MethodSummary& s = r.methods[m];
      char buf[48];
      std::snprintf(buf, sizeof buf, "%d/%d (%.0f%%)", s.stable, s.tested, 100.0 * s.rate());
      row.emplace_back(s.tested > 0 ? buf : "-");
    }
    rows.push_back(row);
  }
  return rows;
}

namespace detail {
inline SvgPanel grasp_panel(const GraspObject& object, const Eigen::Isometry3d& object_pose,
                            std::string caption, bool stable) {
  SvgPanel p;
  p.scene.add(object.composite(object_pose), svg_colours::object, "object");
  p.scene.add_marker(object_pose * object.centre_of_mass(), "centre of mass");
  p.caption = std::move(caption);
  p.caption_colour = stable ? Rgb{30, 130, 50} : Rgb{190, 40, 40};
  return p;
}
}  // namespace detail

/// Writes the figures and index.html of \p results (the demonstrations transferred to hand M) into
/// \p dir (figures under dir/figures): \p per_object grasps of each object (the first stable
/// demonstrations: a human grasp, or with \p sources a robot hand's, drawn as the transfer reads
/// it: its palm, curves and fingertips), and the Fig. 7 and cost plots of the first topological
/// plan. Returns the paths written, relative to \p dir.
/// \throws topograsp::invalid_argument naming "path" if a file cannot be written.
template <const auto& M>
std::vector<std::string> write_report(const std::filesystem::path& dir,
                                      const std::vector<ObjectResultOf<M>>& results,
                                      int per_object = 3,
                                      const std::vector<SourceDemonstration>& sources = {}) {
  std::filesystem::create_directories(dir / "figures");
  const std::string hand(M.name.view());
  const std::string demonstrator = sources.empty() ? "human hand" : sources.front().grasp.hand;
  HtmlPage page;
  page.title = "topograsp: grasp transfer, " + demonstrator + " to " + hand;
  page.intro =
      "Success rate of each transfer method over the stable demonstrations (the stability suite "
      "from the moment the fingers closed: the paper's shake and gravity along the six axis "
      "directions of the hand, the hand without the arm), and for a few grasps the "
      "demonstration beside each transfer, captioned with the suite's verdict.";
  page.header.push_back("");
  for (const ObjectResultOf<M>& r : results) page.header.push_back(r.object.name);
  page.rows = table_rows(results);
  std::vector<std::string> written;
  bool plotted = false;
  for (const ObjectResultOf<M>& r : results) {
    for (std::size_t k = 0; k < r.transferred_ids.size() && static_cast<int>(k) < per_object; ++k) {
      const int id = r.transferred_ids[k];
      std::vector<SvgPanel> panels;
      // A source drawn as the transfer reads it (object frame), a human grasp as demonstrated.
      if (const SourceDemonstration* source = find_source(sources, r.object.name, id)) {
        const SourceGrasp& sg = source->grasp;
        SvgPanel p = detail::grasp_panel(r.object, Eigen::Isometry3d::Identity(),
                                         sg.hand + "\nstable", true);
        for (const Primitive& shape : sg.palm)
          p.scene.add(shape.transformed(sg.root), svg_colours::robot, "hand");
        for (std::size_t c = 0; c < sg.curves.size(); ++c) {
          std::vector<Vec3> points;
          for (const Vec3& x : sg.curves[c]) points.push_back(sg.root * x);
          p.scene.add_polyline(std::move(points), svg_colours::curve(c),
                               "\xCE\xB3" + std::to_string(c + 1));
        }
        for (const SourceDigit& digit : sg.digits) p.scene.add_marker(sg.root * digit.tip, {}, 3.0);
        panels.push_back(std::move(p));
      } else {
        const HumanGrasp& g = *std::find_if(r.human.begin(), r.human.end(),
                                            [&](const HumanGrasp& h) { return h.id == id; });
        KinematicsData<models::human_hand> d;
        forward_kinematics(d, g.q);
        SvgPanel p = detail::grasp_panel(r.object, g.object_pose, "human\nstable", true);
        p.scene.add_model(d, svg_colours::skin, "hand", g.hand_pose);
        p.scene.add_hand_curves(d, g.hand_pose);
        panels.push_back(std::move(p));
      }
      for (std::size_t m = 0; m < r.transfers.size(); ++m) {
        const HandTransfer<M>& t = r.transfers[m][k];
        SvgPanel p = detail::grasp_panel(r.object, t.object_pose,
                                         std::string(to_string(t.method)) + "\n" +
                                             (t.stable()  ? "stable"
                                              : t.planned ? "unstable"
                                                          : "not planned"),
                                         t.stable());
        if (t.planned) {
          KinematicsData<M> d;
          forward_kinematics(d, t.q_closed);
          p.scene.add_model(d, svg_colours::robot, "hand", t.hand_pose);
          p.scene.add_hand_curves(d, t.hand_pose);
        }
        panels.push_back(std::move(p));
      }
      const std::string name =
          "figures/" + file_name_part(r.object.name) + "_" + std::to_string(id) + ".svg";
      write_svg((dir / name).string(),
                svg_panels(panels, r.object.name + ", grasp " + std::to_string(id)));
      written.push_back(name);
      page.figures.push_back({name, r.object.name + ", grasp " + std::to_string(id) +
                                        ": the demonstration and each transfer"});
      for (std::size_t m = 0; m < r.transfers.size() && !plotted; ++m) {
        const HandTransfer<M>& t = r.transfers[m][k];
        if (t.winding_plan.empty()) continue;
        const std::string fig7 =
            "figures/windings_" + file_name_part(r.object.name) + "_" + std::to_string(id) + ".svg";
        constexpr int curves = hand_curve_count<M>;
        std::vector<std::string> labels;
        for (int c = 1; c <= curves; ++c)
          labels.push_back("gamma_" + std::to_string(c) + " (finger " + std::to_string(c) + ")");
        winding_plot<curves>(
            t.winding_plan, t.winding_targets,
            "Windings of the " + hand + "'s curves over the plan (" + r.object.name + ")",
            "time step t", labels)
            .write((dir / fig7).string());
        const std::string cost =
            "figures/cost_" + file_name_part(r.object.name) + "_" + std::to_string(id) + ".svg";
        cost_plot(t.sweep_log).write((dir / cost).string());
        written.push_back(fig7);
        written.push_back(cost);
        page.figures.push_back({fig7, "The winding values of the plan (Fig. 7); dashed: targets"});
        page.figures.push_back({cost, "AICO's cost per sweep for the same plan"});
        plotted = true;
      }
    }
  }
  write_html_page((dir / "index.html").string(), page);
  written.emplace_back("index.html");
  return written;
}

}  // namespace topograsp
