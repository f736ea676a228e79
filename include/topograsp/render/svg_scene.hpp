// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// SvgScene: shapes (hand links, an object), hand curves and a centre-of-mass marker drawn to a
/// standalone SVG with an orthographic camera, flat shading and depth ordering; svg_panels()
/// puts several renderings side by side with a caption each.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/composite.hpp>
#include <topograsp/geometry/model_shapes.hpp>
#include <topograsp/io/text_file.hpp>
#include <topograsp/render/detail/svg_mesh.hpp>
#include <topograsp/render/svg_camera.hpp>
#include <topograsp/task/hand_curve.hpp>

namespace topograsp {

/// A scene of convex shapes, polylines and markers, rendered to SVG.
///
/// Each shape is tessellated into flat polygons, shaded by Lambert's law with one light fixed
/// to the camera (ambient 0.35), back faces are culled and the rest drawn far to near (the
/// painter's algorithm, by polygon centroid). Polylines (the hand curves) and markers (the
/// centre of mass) are drawn on top, then a legend of the labelled ones, the title and the
/// caption. The output depends only on the scene and the camera (coordinates with two
/// decimals).
///
/// Example:
/// \code
///   SvgScene scene;
///   scene.add(object.composite(), svg_colours::wood, "object");
///   scene.add_model(d, svg_colours::skin, "hand");   // after forward_kinematics(d, q)
///   scene.add_hand_curves(d);
///   scene.add_marker(com, "centre of mass");
///   scene.write("grasp.svg", SvgCamera{});
/// \endcode
class SvgScene {
 public:
  /// A polyline drawn over the shapes.
  struct Polyline {
    std::vector<Vec3> points;  ///< world (m)
    Rgb colour;
    std::string label;   ///< legend text; empty: not in the legend
    double width = 2.5;  ///< stroke width (px)
  };
  /// A marker (a centre-of-mass symbol) drawn over the shapes.
  struct Marker {
    Vec3 position = Vec3::Zero();  ///< world (m)
    std::string label;             ///< legend text; empty: not in the legend
    double radius = 6.0;           ///< px
  };

  /// Adds the shape \p shape drawn in \p colour, of the group \p group (the class attribute
  /// of its polygons).
  /// \throws topograsp::invalid_argument naming "shape" if its pose or size is not finite or
  ///         its size is not positive.
  SvgScene& add(const Primitive& shape, Rgb colour, std::string_view group = "shape") {
    check_shape(shape, "shape");
    items_.push_back({shape, colour, group_index(group)});
    return *this;
  }

  /// Adds the shapes \p shapes in \p colour, of the group \p group.
  /// \throws topograsp::invalid_argument naming "shapes" if one is not a valid primitive.
  SvgScene& add(std::span<const Primitive> shapes, Rgb colour, std::string_view group = "shape") {
    for (const Primitive& s : shapes) check_shape(s, "shapes");
    const int g = group_index(group);
    for (const Primitive& s : shapes) items_.push_back({s, colour, g});
    return *this;
  }

  /// Adds the parts of \p object in \p colour, of the group \p group.
  SvgScene& add(const Composite& object, Rgb colour, std::string_view group = "object") {
    return add(object.parts(), colour, group);
  }

  /// Adds every shape of the model \p M at the kinematics result \p d, moved by \p T_world_base
  /// (for a fixed-base hand placed at a pose, e.g. HumanGrasp::hand_pose). Requires
  /// forward_kinematics(d, q) first.
  /// \throws topograsp::invalid_argument naming "d" if a shape is not finite, or
  ///         "T_world_base" if that is not finite.
  template <const auto& M>
  SvgScene& add_model(const KinematicsData<M>& d, Rgb colour, std::string_view group = "hand",
                      const Eigen::Isometry3d& T_world_base = Eigen::Isometry3d::Identity()) {
    require_finite(T_world_base.matrix(), "T_world_base");
    const auto shapes = world_shapes(d);
    for (const Primitive& s : shapes) check_shape(s, "d");
    const int g = group_index(group);
    for (const Primitive& s : shapes) items_.push_back({s.transformed(T_world_base), colour, g});
    return *this;
  }

  /// Adds the hand curves gamma_1 .. gamma_n of the hand model \p M at \p d (moved by
  /// \p T_world_base), each in svg_colours::curve(i) with the legend label "γi (finger)".
  /// Requires forward_kinematics(d, q) first.
  /// \throws topograsp::invalid_argument naming "d" or "T_world_base" if not finite.
  template <const auto& M>
    requires HandModel<decltype(M)>
  SvgScene& add_hand_curves(const KinematicsData<M>& d,
                            const Eigen::Isometry3d& T_world_base = Eigen::Isometry3d::Identity()) {
    require_finite(T_world_base.matrix(), "T_world_base");
    std::array<Vec3, static_cast<std::size_t>(hand_curve_capacity<M>)> pts{};
    std::vector<Polyline> lines;
    for (int i = 0; i < hand_curve_count<M>; ++i) {
      const int n = hand_curve_points(d, i, pts);
      Polyline l;
      for (int k = 0; k < n; ++k) {
        const Vec3 x = T_world_base * pts[static_cast<std::size_t>(k)];
        require_finite(x, "d");
        l.points.push_back(x);
      }
      l.colour = svg_colours::curve(static_cast<std::size_t>(i));
      const auto finger =
          static_cast<std::size_t>(hand_curves_of<M>[static_cast<std::size_t>(i)].finger);
      l.label = "\xCE\xB3" + std::to_string(i + 1) + " (" +
                std::string(M.fingers[finger].spec.name.view()) + ")";
      lines.push_back(std::move(l));
    }
    for (Polyline& l : lines) polylines_.push_back(std::move(l));
    return *this;
  }

  /// Adds a polyline through \p points (world, m) in \p colour, with the legend \p label (empty:
  /// none).
  /// \throws topograsp::invalid_argument naming "points" if a point is not finite, or "width" if
  ///         the stroke width is not positive.
  SvgScene& add_polyline(std::vector<Vec3> points, Rgb colour, std::string label = {},
                         double width = 2.5) {
    for (const Vec3& x : points) require_finite(x, "points");
    require_positive(width, "width");
    polylines_.push_back({std::move(points), colour, std::move(label), width});
    return *this;
  }

  /// Adds a centre-of-mass marker (a circle with two black quarters) at \p position (world, m),
  /// with the legend \p label (empty: none).
  /// \throws topograsp::invalid_argument naming "position" if it is not finite.
  SvgScene& add_marker(const Vec3& position, std::string label = {}, double radius = 6.0) {
    require_finite(position, "position");
    require_positive(radius, "radius");
    markers_.push_back({position, std::move(label), radius});
    return *this;
  }

  /// Sets the title, drawn centred at the top.
  SvgScene& set_title(std::string title) {
    title_ = std::move(title);
    return *this;
  }
  /// Sets the caption, drawn centred at the bottom; '\n' starts a new line.
  SvgScene& set_caption(std::string caption) {
    caption_ = std::move(caption);
    return *this;
  }

  [[nodiscard]] std::size_t shape_count() const noexcept { return items_.size(); }
  [[nodiscard]] const std::vector<Polyline>& polylines() const noexcept { return polylines_; }
  [[nodiscard]] const std::vector<Marker>& markers() const noexcept { return markers_; }
  [[nodiscard]] bool empty() const noexcept {
    return items_.empty() && polylines_.empty() && markers_.empty();
  }

  /// The zoom (pixels per metre) that fits the scene into \p camera's image (its zoom ignored);
  /// 0 for an empty scene.
  /// \throws topograsp::invalid_argument naming the bad camera field.
  [[nodiscard]] double fit_zoom(const SvgCamera& camera) const {
    check_camera(camera);
    const Frame f = frame_of(camera);
    const detail::Mesh mesh = tessellate(camera);
    return fit(camera, f, mesh).zoom;
  }

  /// The SVG elements of the rendering (no <svg> root) for an image of camera.width x
  /// camera.height with its origin at the top left; for embedding.
  /// \throws topograsp::invalid_argument naming the bad camera field ("camera.direction",
  ///         "camera.up", "camera.zoom", "camera.width", "camera.height", "camera.target",
  ///         "camera.segments", "camera.margin", "camera.max_edge", "camera.light").
  [[nodiscard]] std::string svg_body(const SvgCamera& camera) const {
    check_camera(camera);
    const Frame f = frame_of(camera);
    const detail::Mesh mesh = tessellate(camera);
    const View v = fit(camera, f, mesh);
    const auto project = [&](const Vec3& x) {
      const Vec3 d = x - v.target;
      return std::pair<double, double>(v.cx + v.zoom * d.dot(f.right), v.cy - v.zoom * d.dot(f.up));
    };
    std::string o;
    // Faces: culled, sorted far to near (ties: scene order), flat-shaded.
    std::vector<std::pair<double, int>> order;
    order.reserve(mesh.faces.size());
    for (std::size_t i = 0; i < mesh.faces.size(); ++i) {
      const detail::MeshFace& face = mesh.faces[i];
      if (face.normal.dot(f.forward) >= -1e-9) continue;  // facing away or edge-on
      order.emplace_back(face.centroid.dot(f.forward), static_cast<int>(i));
    }
    std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    const Vec3 light =
        (camera.light[0] * f.right + camera.light[1] * f.up - camera.light[2] * f.forward)
            .normalized();
    if (!order.empty()) o += "<g stroke-width=\"0.6\" stroke-linejoin=\"round\">\n";
    for (const auto& [depth, index] : order) {
      const detail::MeshFace& face = mesh.faces[static_cast<std::size_t>(index)];
      const Item& item = items_[static_cast<std::size_t>(face.item)];
      const double shade = 0.35 + 0.65 * std::max(0.0, face.normal.dot(light));
      const std::string c = hex(scaled(item.colour, shade));
      o += "<polygon class=\"" + detail::xml_escape(groups_[static_cast<std::size_t>(item.group)]) +
           "\" points=\"";
      for (int k = 0; k < face.count; ++k) {
        const auto [x, y] = project(mesh.vertices[static_cast<std::size_t>(face.first + k)]);
        if (k > 0) o += ' ';
        o += detail::svg_number(x) + "," + detail::svg_number(y);
      }
      o += "\" fill=\"" + c + "\" stroke=\"" + c + "\"/>\n";
    }
    if (!order.empty()) o += "</g>\n";
    // Polylines and markers on top.
    for (const Polyline& l : polylines_) {
      if (l.points.empty()) continue;
      o += "<polyline fill=\"none\" stroke=\"" + hex(l.colour) + "\" stroke-width=\"" +
           detail::svg_number(l.width) +
           "\" stroke-linejoin=\"round\" stroke-linecap=\"round\" points=\"";
      for (std::size_t k = 0; k < l.points.size(); ++k) {
        const auto [x, y] = project(l.points[k]);
        if (k > 0) o += ' ';
        o += detail::svg_number(x) + "," + detail::svg_number(y);
      }
      o += "\"/>\n";
    }
    for (const Marker& m : markers_) {
      const auto [x, y] = project(m.position);
      o += marker(x, y, m.radius);
    }
    // Legend of the labelled polylines and markers, top left.
    double ly = camera.margin + (title_.empty() ? 0.0 : 24.0) + 6.0;
    const double lx = camera.margin;
    for (const Polyline& l : polylines_) {
      if (l.label.empty()) continue;
      o += "<line x1=\"" + detail::svg_number(lx) + "\" y1=\"" + detail::svg_number(ly) +
           "\" x2=\"" + detail::svg_number(lx + 22) + "\" y2=\"" + detail::svg_number(ly) +
           "\" stroke=\"" + hex(l.colour) + "\" stroke-width=\"" + detail::svg_number(l.width) +
           "\"/>\n";
      o += text(lx + 28, ly + 4, l.label, "start", 12);
      ly += 17;
    }
    for (const Marker& m : markers_) {
      if (m.label.empty()) continue;
      o += marker(lx + 11, ly, std::min(m.radius, 6.0));
      o += text(lx + 28, ly + 4, m.label, "start", 12);
      ly += 17;
    }
    if (!title_.empty()) o += text(0.5 * camera.width, camera.margin + 12, title_, "middle", 15);
    const std::vector<std::string> lines = split_lines(caption_);
    for (std::size_t k = 0; k < lines.size(); ++k)
      o += text(
          0.5 * camera.width,
          camera.height - camera.margin * 0.5 - 16.0 * static_cast<double>(lines.size() - 1 - k),
          lines[k], "middle", 13);
    return o;
  }

  /// The rendering as a standalone SVG document (white background).
  /// \throws topograsp::invalid_argument naming the bad camera field (see svg_body()).
  [[nodiscard]] std::string svg(const SvgCamera& camera = {}) const {
    std::string body = svg_body(camera);
    return svg_document(camera.width, camera.height, body);
  }

  /// Writes svg(camera) to \p path.
  /// \throws topograsp::invalid_argument naming "path" if it cannot be written, or the bad
  ///         camera field.
  void write(const std::string& path, const SvgCamera& camera = {}) const {
    detail::write_text_file(path, svg(camera));
  }

  /// "#rrggbb" of \p c.
  [[nodiscard]] static std::string hex(Rgb c) {
    char b[8];
    std::snprintf(b, sizeof b, "#%02x%02x%02x", static_cast<unsigned>(c.r),
                  static_cast<unsigned>(c.g), static_cast<unsigned>(c.b));
    return b;
  }

  /// A standalone SVG document of \p width x \p height pixels with a white background around
  /// the elements \p body.
  [[nodiscard]] static std::string svg_document(int width, int height, std::string_view body) {
    std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    const std::string w = std::to_string(width), h = std::to_string(height);
    o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "\" height=\"" + h +
         "\" viewBox=\"0 0 " + w + " " + h + "\" font-family=\"sans-serif\">\n";
    o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    o += body;
    o += "</svg>\n";
    return o;
  }

  /// A <text> element at (\p x, \p y) with \p anchor ("start", "middle", "end"), escaped.
  [[nodiscard]] static std::string text(double x, double y, std::string_view s,
                                        std::string_view anchor, int font_size, Rgb colour = {}) {
    std::string o = "<text x=\"" + detail::svg_number(x) + "\" y=\"" + detail::svg_number(y) +
                    "\" text-anchor=\"" + std::string(anchor) + "\" font-size=\"" +
                    std::to_string(font_size) + "\"";
    if (!(colour == Rgb{})) o += " fill=\"" + hex(colour) + "\"";
    return o + ">" + detail::xml_escape(s) + "</text>\n";
  }

  /// The lines of \p s split at '\n' (none for an empty string).
  [[nodiscard]] static std::vector<std::string> split_lines(std::string_view s) {
    std::vector<std::string> out;
    if (s.empty()) return out;
    std::size_t start = 0;
    for (;;) {
      const std::size_t end = s.find('\n', start);
      out.emplace_back(s.substr(start, end == std::string_view::npos ? s.npos : end - start));
      if (end == std::string_view::npos) break;
      start = end + 1;
    }
    return out;
  }

 private:
  struct Item {
    Primitive shape;
    Rgb colour;
    int group = 0;
  };
  struct Frame {
    Vec3 forward, right, up;
  };
  struct View {
    double zoom = 1.0;
    Vec3 target = Vec3::Zero();
    double cx = 0.0, cy = 0.0;  // image point of the target (px)
  };

  static Rgb scaled(Rgb c, double k) {
    const auto channel = [k](std::uint8_t x) {
      const double v = std::round(k * static_cast<double>(x));
      return static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0));
    };
    return {channel(c.r), channel(c.g), channel(c.b)};
  }

  static void check_shape(const Primitive& s, std::string_view argument) {
    const bool finite = s.R.allFinite() && s.p.allFinite() && s.size.allFinite();
    const bool sized = s.type == ShapeType::box
                           ? (s.size.array() > 0.0).all()
                           : s.size[0] > 0.0 && (s.type == ShapeType::sphere || s.size[1] >= 0.0);
    if (!finite) detail::throw_invalid_argument(argument, "expected a finite pose and size");
    if (!sized) detail::throw_invalid_argument(argument, "expected a positive size");
  }

  static void check_camera(const SvgCamera& c) {
    require_finite(c.direction, "camera.direction");
    if (!(c.direction.norm() > 1e-12))
      detail::throw_invalid_argument("camera.direction", "expected a nonzero direction");
    require_finite(c.up, "camera.up");
    if (!(c.up.norm() > 1e-12) ||
        !(c.direction.normalized().cross(c.up.normalized()).norm() > 1e-6))
      detail::throw_invalid_argument("camera.up", "expected a vector not along the direction");
    require_non_negative(c.zoom, "camera.zoom");
    if (c.width < 16) detail::throw_invalid_argument("camera.width", "expected at least 16 px");
    if (c.height < 16) detail::throw_invalid_argument("camera.height", "expected at least 16 px");
    if (c.target) require_finite(*c.target, "camera.target");
    if (c.segments < 4 || c.segments > 128)
      detail::throw_invalid_argument("camera.segments", "expected 4 to 128 segments");
    require_non_negative(c.margin, "camera.margin");
    require_non_negative(c.max_edge, "camera.max_edge");
    require_finite(c.light, "camera.light");
    if (!(c.light.norm() > 1e-12))
      detail::throw_invalid_argument("camera.light", "expected a nonzero direction");
  }

  // forward along the view, right = forward x up, up = right x forward (orthonormal).
  static Frame frame_of(const SvgCamera& c) {
    Frame f;
    f.forward = c.direction.normalized();
    f.right = f.forward.cross(c.up).normalized();
    f.up = f.right.cross(f.forward);
    return f;
  }

  int group_index(std::string_view group) {
    for (std::size_t i = 0; i < groups_.size(); ++i)
      if (groups_[i] == group) return static_cast<int>(i);
    groups_.emplace_back(group);
    return static_cast<int>(groups_.size() - 1);
  }

  detail::Mesh tessellate(const SvgCamera& camera) const {
    double max_edge = camera.max_edge;
    if (max_edge == 0.0 && !items_.empty()) {
      Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
      for (const Item& it : items_) {
        const double r = it.shape.bounding_radius();
        lo = lo.cwiseMin(it.shape.p - Vec3::Constant(r));
        hi = hi.cwiseMax(it.shape.p + Vec3::Constant(r));
      }
      max_edge = 0.1 * (hi - lo).maxCoeff();
    }
    detail::Mesh mesh;
    for (std::size_t i = 0; i < items_.size(); ++i)
      detail::tessellate(mesh, items_[i].shape, camera.segments, max_edge, static_cast<int>(i));
    return mesh;
  }

  // Where the target is and how large: fitted to the projected bounding box of every vertex,
  // polyline point and marker, inside the image minus the margins, title and caption.
  View fit(const SvgCamera& camera, const Frame& f, const detail::Mesh& mesh) const {
    double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
    const auto grow = [&](const Vec3& x) {
      const double u = x.dot(f.right), v = x.dot(f.up);
      u0 = std::min(u0, u), u1 = std::max(u1, u), v0 = std::min(v0, v), v1 = std::max(v1, v);
    };
    for (const Vec3& x : mesh.vertices) grow(x);
    for (const Polyline& l : polylines_)
      for (const Vec3& x : l.points) grow(x);
    for (const Marker& m : markers_) grow(m.position);
    const double top = camera.margin + (title_.empty() ? 0.0 : 24.0);
    const double bottom = camera.margin + 16.0 * static_cast<double>(split_lines(caption_).size());
    const double aw = std::max(1.0, camera.width - 2.0 * camera.margin);
    const double ah = std::max(1.0, camera.height - top - bottom);
    View v;
    v.cx = 0.5 * camera.width;
    v.cy = top + 0.5 * ah;
    if (!std::isfinite(u0)) {  // nothing to draw
      v.zoom = camera.zoom > 0.0 ? camera.zoom : 0.0;
      v.target = camera.target.value_or(Vec3::Zero());
      return v;
    }
    const Vec3 centre = (0.5 * (u0 + u1)) * f.right + (0.5 * (v0 + v1)) * f.up;
    if (camera.zoom > 0.0) {
      v.zoom = camera.zoom;
      v.target = camera.target.value_or(centre);
      return v;
    }
    const double du = u1 - u0, dv = v1 - v0;
    if (du <= 0.0 && dv <= 0.0)
      v.zoom = 1.0;
    else if (du <= 0.0)
      v.zoom = ah / dv;
    else if (dv <= 0.0)
      v.zoom = aw / du;
    else
      v.zoom = std::min(aw / du, ah / dv);
    v.target = centre;
    return v;
  }

  static std::string marker(double x, double y, double r) {
    const std::string sx = detail::svg_number(x), sy = detail::svg_number(y),
                      sr = detail::svg_number(r);
    std::string o = "<circle cx=\"" + sx + "\" cy=\"" + sy + "\" r=\"" + sr +
                    "\" fill=\"white\" stroke=\"black\" stroke-width=\"1.2\"/>\n";
    o += "<path d=\"M" + sx + " " + sy + " L" + detail::svg_number(x + r) + " " + sy + " A" + sr +
         " " + sr + " 0 0 1 " + sx + " " + detail::svg_number(y + r) + " Z M" + sx + " " + sy +
         " L" + detail::svg_number(x - r) + " " + sy + " A" + sr + " " + sr + " 0 0 1 " + sx + " " +
         detail::svg_number(y - r) + " Z\" fill=\"black\"/>\n";
    return o;
  }

  std::vector<Item> items_;
  std::vector<std::string> groups_;
  std::vector<Polyline> polylines_;
  std::vector<Marker> markers_;
  std::string title_, caption_;
};

/// Writes the SVG document \p svg (from SvgScene::svg() or svg_panels(), render/svg_panels.hpp) to
/// \p path.
/// \throws topograsp::invalid_argument naming "path" if it cannot be written.
inline void write_svg(const std::string& path, std::string_view svg) {
  detail::write_text_file(path, svg);
}

}  // namespace topograsp
