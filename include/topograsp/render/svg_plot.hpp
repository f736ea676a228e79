// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// SvgLinePlot: a small dependency-free SVG line-plot writer (axes, ticks, labels, legend); and
/// the two plots of a run: winding_plot() (the paper's Fig. 7) and cost_plot() (AICO's cost per
/// sweep).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <topograsp/aico/result.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/io/text_file.hpp>

namespace topograsp {

/// How SvgLinePlot draws one series.
struct SvgSeriesStyle {
  std::string colour;    ///< an SVG colour ("#d62728"); empty: the next colour of the palette
  bool dashed = false;   ///< a dashed line (e.g. a target)
  bool line = true;      ///< draw the line through the points
  bool markers = false;  ///< draw a dot at every point
  double width = 2.0;    ///< stroke width (px)
};

/// A line plot of one or more series written as a standalone SVG document: a frame with "nice"
/// ticks (1, 2 or 5 times a power of ten) on both axes, axis labels, a title and a legend.
///
/// Example: `SvgLinePlot p("Windings", "step t", "w"); p.add_series("gamma_1", t, w1);
/// p.write("windings.svg");`
class SvgLinePlot {
 public:
  /// A plot with \p title and axis labels \p x_label, \p y_label, \p width x \p height pixels.
  explicit SvgLinePlot(std::string title = {}, std::string x_label = {}, std::string y_label = {},
                       int width = 720, int height = 440)
      : title_(std::move(title)),
        x_label_(std::move(x_label)),
        y_label_(std::move(y_label)),
        width_(width),
        height_(height) {
    if (width < 200 || height < 150)
      detail::throw_invalid_argument("width", "expected a plot of at least 200 x 150 pixels");
  }

  /// Adds a series drawn as a polyline through (x[i], y[i]), with \p label in the legend.
  /// \throws topograsp::invalid_argument naming "x" or "y" if the sizes differ, a series is
  ///         empty or a value is not finite.
  void add_series(std::string label, std::vector<double> x, std::vector<double> y) {
    if (x.empty() || x.size() != y.size())
      detail::throw_invalid_argument("y", "expected as many values as x, and at least one");
    for (double v : x) require_finite(v, "x");
    for (double v : y) require_finite(v, "y");
    if (log_y_)
      for (double v : y)
        if (!(v > 0.0)) detail::throw_invalid_argument("y", "expected values > 0 on a log axis");
    series_.push_back({std::move(label), std::move(x), std::move(y), {}, false});
  }

  /// Adds a series as add_series() does, drawn with \p style.
  /// \throws topograsp::invalid_argument naming "x" or "y" as add_series() does, or "style" for
  ///         a non-positive width or a style that draws neither line nor markers.
  void add_series(std::string label, std::vector<double> x, std::vector<double> y,
                  SvgSeriesStyle style) {
    require_positive(style.width, "style");
    if (!style.line && !style.markers)
      detail::throw_invalid_argument("style", "expected a line, markers or both");
    add_series(std::move(label), std::move(x), std::move(y));
    series_.back().style = std::move(style);
    series_.back().styled = true;
  }

  /// Draws the y axis on a log10 scale with ticks at powers of ten.
  /// \throws topograsp::invalid_argument naming "y" if a series has a value <= 0.
  void set_log_y(bool on = true) {
    if (on)
      for (const Series& s : series_)
        for (double v : s.y)
          if (!(v > 0.0)) detail::throw_invalid_argument("y", "expected values > 0 on a log axis");
    if (on)
      for (const auto& r : references_)
        if (!(r.second > 0.0))
          detail::throw_invalid_argument("y", "expected values > 0 on a log axis");
    log_y_ = on;
  }
  [[nodiscard]] bool log_y() const noexcept { return log_y_; }

  /// The colour of the \p k-th unstyled series: the palette #1f77b4, #d62728, #2ca02c, #ff7f0e,
  /// #9467bd, #8c564b, #17becf, cycling (the colours of the hand curves in SvgScene).
  [[nodiscard]] static std::string series_colour(std::size_t k) { return colour(k); }

  /// Adds a dashed horizontal reference line at \p y with \p label (e.g. a target value).
  void add_reference(std::string label, double y) {
    require_finite(y, "y");
    if (log_y_ && !(y > 0.0))
      detail::throw_invalid_argument("y", "expected a value > 0 on a log axis");
    references_.emplace_back(std::move(label), y);
  }

  /// The SVG document.
  [[nodiscard]] std::string str() const {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    const auto ty = [this](double v) { return log_y_ ? std::log10(v) : v; };
    for (const Series& s : series_) {
      for (double v : s.x) x0 = std::min(x0, v), x1 = std::max(x1, v);
      for (double v : s.y) y0 = std::min(y0, ty(v)), y1 = std::max(y1, ty(v));
    }
    for (const auto& r : references_)
      y0 = std::min(y0, ty(r.second)), y1 = std::max(y1, ty(r.second));
    if (!std::isfinite(x0)) x0 = 0.0, x1 = 1.0;
    if (!std::isfinite(y0)) y0 = 0.0, y1 = 1.0;
    const Axis ax = nice_axis(x0, x1), ay = log_y_ ? log_axis(y0, y1) : nice_axis(y0, y1);
    const double left = 70, right = 170, top = 40, bottom = 55;
    const double pw = width_ - left - right, ph = height_ - top - bottom;
    const auto px = [&](double v) { return left + (v - ax.lo) / (ax.hi - ax.lo) * pw; };
    const auto py = [&](double v) { return top + (ax_flip(ty(v), ay))*ph; };
    const auto py_axis = [&](double v) { return top + (ax_flip(v, ay))*ph; };
    std::string o;
    o += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    o += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width_) +
         "\" height=\"" + std::to_string(height_) + "\" viewBox=\"0 0 " + std::to_string(width_) +
         " " + std::to_string(height_) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    o += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    // Grid and ticks.
    for (double v = ax.lo; v <= ax.hi + 0.5 * ax.step; v += ax.step) {
      const double x = px(v);
      o += line(x, top, x, top + ph, "#e0e0e0") + line(x, top + ph, x, top + ph + 5, "black");
      o += text(x, top + ph + 18, number(v, ax.step), "middle");
    }
    for (double v = ay.lo; v <= ay.hi + 0.5 * ay.step; v += ay.step) {
      const double y = py_axis(v);
      o += line(left, y, left + pw, y, "#e0e0e0") + line(left - 5, y, left, y, "black");
      if (log_y_)
        o += "<text x=\"" + fmt(left - 8) + "\" y=\"" + fmt(y + 4) +
             "\" text-anchor=\"end\" >10<tspan dy=\"-6\" font-size=\"9\">" + number(v, 1.0) +
             "</tspan></text>\n";
      else
        o += text(left - 8, y + 4, number(v, ay.step), "end");
    }
    o += "<rect x=\"" + fmt(left) + "\" y=\"" + fmt(top) + "\" width=\"" + fmt(pw) +
         "\" height=\"" + fmt(ph) + "\" fill=\"none\" stroke=\"black\"/>\n";
    // Labels.
    o += text(left + 0.5 * pw, 22, title_, "middle", "font-size=\"15\"");
    o += text(left + 0.5 * pw, height_ - 12, x_label_, "middle");
    o += "<text x=\"18\" y=\"" + fmt(top + 0.5 * ph) +
         "\" text-anchor=\"middle\" transform=\"rotate(-90 18 " + fmt(top + 0.5 * ph) + ")\">" +
         escape(y_label_) + "</text>\n";
    // Data, references and legend.
    std::size_t k = 0;
    double ly = top + 10;
    for (const Series& s : series_) {
      std::string c = colour(k++);
      if (!s.styled) {
        o += "<polyline fill=\"none\" stroke=\"" + c + "\" stroke-width=\"2\" points=\"";
        for (std::size_t i = 0; i < s.x.size(); ++i)
          o += fmt(px(s.x[i])) + "," + fmt(py(s.y[i])) + " ";
        o += "\"/>\n";
        o += line(left + pw + 15, ly, left + pw + 40, ly, c, "stroke-width=\"2\"");
        o += text(left + pw + 46, ly + 4, s.label, "start");
        ly += 20;
        continue;
      }
      if (!s.style.colour.empty()) c = escape(s.style.colour);
      const std::string w = "stroke-width=\"" + fmt(s.style.width) + "\"" +
                            (s.style.dashed ? " stroke-dasharray=\"6 4\"" : "");
      if (s.style.line) {
        o += "<polyline fill=\"none\" stroke=\"" + c + "\" " + w + " points=\"";
        for (std::size_t i = 0; i < s.x.size(); ++i)
          o += fmt(px(s.x[i])) + "," + fmt(py(s.y[i])) + " ";
        o += "\"/>\n";
        o += line(left + pw + 15, ly, left + pw + 40, ly, c, w);
      }
      if (s.style.markers) {
        for (std::size_t i = 0; i < s.x.size(); ++i)
          o += dot(px(s.x[i]), py(s.y[i]), s.style.width + 1.0, c);
        o += dot(left + pw + 27.5, ly, s.style.width + 1.0, c);
      }
      o += text(left + pw + 46, ly + 4, s.label, "start");
      ly += 20;
    }
    for (const auto& [label, v] : references_) {
      const std::string c = colour(k++);
      o += line(left, py(v), left + pw, py(v), c, "stroke-dasharray=\"6 4\"");
      o += line(left + pw + 15, ly, left + pw + 40, ly, c, "stroke-dasharray=\"6 4\"");
      o += text(left + pw + 46, ly + 4, label, "start");
      ly += 20;
    }
    o += "</svg>\n";
    return o;
  }

  /// Writes the SVG document to \p path.
  /// \throws topograsp::invalid_argument naming "path" if the file cannot be written.
  void write(const std::string& path) const { detail::write_text_file(path, str()); }

 private:
  struct Series {
    std::string label;
    std::vector<double> x, y;
    SvgSeriesStyle style;
    bool styled = false;  // false: the original look (palette colour, solid 2 px line)
  };
  struct Axis {
    double lo, hi, step;
  };

  // An axis from lo to hi widened to multiples of a step of 1, 2 or 5 times a power of ten,
  // with about 4 to 10 ticks.
  static Axis nice_axis(double lo, double hi) {
    if (hi - lo <= 1e-12 * std::max(1.0, std::abs(lo))) {
      const double pad = std::max(0.5, 0.1 * std::abs(lo));
      lo -= pad;
      hi += pad;
    }
    const double raw = (hi - lo) / 6.0;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10.0 * mag;
    for (double m : {1.0, 2.0, 5.0})
      if (m * mag >= raw) {
        step = m * mag;
        break;
      }
    return {std::floor(lo / step) * step, std::ceil(hi / step) * step, step};
  }
  // A log axis over the exponents lo..hi: whole decades, a step of 1, 2, 5, ... decades.
  static Axis log_axis(double lo, double hi) {
    double a = std::floor(lo + 1e-9), b = std::ceil(hi - 1e-9);
    if (b <= a) a -= 1.0, b += 1.0;
    double step = 1.0;
    while ((b - a) / step > 8.0) step *= (step == 1.0 || step == 10.0 ? 2.0 : 2.5);
    return {std::floor(a / step) * step, std::ceil(b / step) * step, step};
  }
  static std::string dot(double x, double y, double r, const std::string& colour) {
    return "<circle cx=\"" + fmt(x) + "\" cy=\"" + fmt(y) + "\" r=\"" + fmt(r) + "\" fill=\"" +
           colour + "\"/>\n";
  }
  static double ax_flip(double v, const Axis& a) { return (a.hi - v) / (a.hi - a.lo); }
  static std::string fmt(double v) { return detail::svg_number(v); }
  // A tick label: as many decimals as the step needs.
  static std::string number(double v, double step) {
    const int digits = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
    return detail::svg_number(std::abs(v) < 0.5 * step ? 0.0 : v, digits);
  }
  static std::string escape(std::string_view s) { return detail::xml_escape(s); }
  static std::string line(double x1, double y1, double x2, double y2, const std::string& colour,
                          const std::string& extra = {}) {
    return "<line x1=\"" + fmt(x1) + "\" y1=\"" + fmt(y1) + "\" x2=\"" + fmt(x2) + "\" y2=\"" +
           fmt(y2) + "\" stroke=\"" + colour + "\" " + extra + "/>\n";
  }
  static std::string text(double x, double y, std::string_view s, const char* anchor,
                          const std::string& extra = {}) {
    return "<text x=\"" + fmt(x) + "\" y=\"" + fmt(y) + "\" text-anchor=\"" + anchor + "\" " +
           extra + ">" + escape(s) + "</text>\n";
  }
  static std::string colour(std::size_t k) {
    static constexpr const char* palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                              "#9467bd", "#8c564b", "#17becf"};
    return palette[k % (sizeof palette / sizeof palette[0])];
  }

  std::string title_, x_label_, y_label_;
  int width_, height_;
  std::vector<Series> series_;
  std::vector<std::pair<std::string, double>> references_;
  bool log_y_ = false;
};

/// The winding values of K hand curves over the time steps of a trajectory (the paper's
/// Fig. 7): one solid line per curve, "w(γi)", in the curve's colour, and, if \p targets is
/// given (as many steps as \p values), the targets y_i dashed in the same colour.
///
/// \param values phi(q_t) for t = 0..T, e.g. TopologicalResult::values
/// \param targets y_t for t = 0..T (e.g. TopologicalResult::targets), or empty
/// \param labels the curve names (default "γ1", "γ2", ...), K of them or none
/// \throws topograsp::invalid_argument naming "targets" or "labels" for a wrong count, or "y"
///         for a non-finite value.
template <int K>
[[nodiscard]] SvgLinePlot winding_plot(const std::vector<Vec<K>>& values,
                                       const std::vector<Vec<K>>& targets = {},
                                       std::string title = "Winding numbers over time",
                                       std::string x_label = "time step t",
                                       const std::vector<std::string>& labels = {}) {
  if (!targets.empty() && targets.size() != values.size())
    detail::throw_invalid_argument("targets", "expected none or as many steps as values");
  if (!labels.empty() && labels.size() != static_cast<std::size_t>(K))
    detail::throw_invalid_argument("labels", "expected none or one label per curve");
  SvgLinePlot plot(std::move(title), std::move(x_label), "winding w", 720, 440);
  if (values.empty()) return plot;
  std::vector<double> t(values.size());
  for (std::size_t u = 0; u < t.size(); ++u) t[u] = static_cast<double>(u);
  const auto name = [&](int i) {
    return labels.empty() ? "\xCE\xB3" + std::to_string(i + 1)
                          : labels[static_cast<std::size_t>(i)];
  };
  for (int i = 0; i < K; ++i) {
    std::vector<double> w(values.size());
    for (std::size_t u = 0; u < w.size(); ++u) w[u] = values[u][i];
    SvgSeriesStyle style;
    style.colour = SvgLinePlot::series_colour(static_cast<std::size_t>(i));
    style.width = 2.5;
    plot.add_series("w(" + name(i) + ")", t, std::move(w), style);
  }
  if (!targets.empty())
    for (int i = 0; i < K; ++i) {
      std::vector<double> y(targets.size());
      for (std::size_t u = 0; u < y.size(); ++u) y[u] = targets[u][i];
      SvgSeriesStyle style;
      style.colour = SvgLinePlot::series_colour(static_cast<std::size_t>(i));
      style.dashed = true;
      style.width = 1.5;
      plot.add_series("target y(" + name(i) + ")", t, std::move(y), style);
    }
  return plot;
}

/// The cost of each sweep of an AICO run (AicoResult::sweep_log) against the sweep number
/// (1-based): a line with a dot per sweep, and the accepted sweeps as larger green dots. The y
/// axis is logarithmic when every cost is > 0 and they span more than a factor of 100.
/// \throws topograsp::invalid_argument naming "sweeps" if a cost is not finite.
[[nodiscard]] inline SvgLinePlot cost_plot(std::span<const AicoSweepRecord> sweeps,
                                           std::string title = "AICO cost per sweep") {
  SvgLinePlot plot(std::move(title), "sweep", "cost", 720, 440);
  if (sweeps.empty()) return plot;
  std::vector<double> n, c, an, ac;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t k = 0; k < sweeps.size(); ++k) {
    const double v = sweeps[k].cost;
    require_finite(v, "sweeps");
    n.push_back(static_cast<double>(k + 1));
    c.push_back(v);
    lo = std::min(lo, v), hi = std::max(hi, v);
    if (sweeps[k].accepted) an.push_back(static_cast<double>(k + 1)), ac.push_back(v);
  }
  SvgSeriesStyle all;
  all.colour = SvgLinePlot::series_colour(0);
  all.markers = true;
  all.width = 1.5;
  plot.add_series("cost of the sweep", std::move(n), std::move(c), all);
  if (!an.empty()) {
    SvgSeriesStyle accepted;
    accepted.colour = SvgLinePlot::series_colour(2);
    accepted.line = false;
    accepted.markers = true;
    accepted.width = 3.0;
    plot.add_series("accepted", std::move(an), std::move(ac), accepted);
  }
  if (lo > 0.0 && hi > 100.0 * lo) plot.set_log_y();
  return plot;
}

}  // namespace topograsp
