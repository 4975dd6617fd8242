#include "app/bench/svg_plot.h"

#include "app/common/xml_escape.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>
#include <sstream>

namespace skylit::app::bench {
namespace {

// Panel geometry (px): plot area inside the margins.
constexpr double kPanelW = 560, kPanelH = 380;
constexpr double kLeft = 72, kRight = 24, kTop = 44, kBottom = 52;

std::string fmt(double v, const char* format = "%.1f") {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

struct Series {
  std::string title;  // y-axis and panel title
  std::function<double(const BenchRow&)> error;
};

// One panel at (x0, y0): axes, ticks, points, front, labels of front points.
void draw_panel(std::ostringstream& svg, double x0, double y0, const std::string& title,
                const std::vector<const BenchRow*>& rows, const Series& series) {
  std::vector<PlotPoint> points;
  std::vector<const BenchRow*> kept;
  for (const BenchRow* r : rows) {
    const double e = series.error(*r);
    if (std::isfinite(e) && r->frame_ms.median > 0) {
      points.push_back({r->frame_ms.median, e});
      kept.push_back(r);
    }
  }
  const double w = kPanelW - kLeft - kRight, h = kPanelH - kTop - kBottom;
  const double px = x0 + kLeft, py = y0 + kTop;
  svg << "<g class=\"panel\">\n<text x=\"" << fmt(px + w / 2) << "\" y=\"" << fmt(y0 + 24)
      << "\" text-anchor=\"middle\" font-weight=\"bold\">" << xml_escape(title + ": " + series.title) << "</text>\n";
  svg << "<rect x=\"" << fmt(px) << "\" y=\"" << fmt(py) << "\" width=\"" << fmt(w) << "\" height=\"" << fmt(h)
      << "\" fill=\"none\" stroke=\"#444\"/>\n";
  if (points.empty()) {
    svg << "</g>\n";
    return;
  }
  // x: decades of milliseconds covering the points. y: 0 … 1.1 × the largest error,
  // or decades when the errors span more than one (a poor setting would otherwise
  // squash the front against the axis).
  double lo = 1e300, hi = 0, emin = 1e300, emax = 0;
  for (const auto& p : points) {
    lo = std::min(lo, p.ms), hi = std::max(hi, p.ms);
    emin = std::min(emin, p.error), emax = std::max(emax, p.error);
  }
  const double d0 = std::floor(std::log10(lo)), d1 = std::max(d0 + 1, std::ceil(std::log10(hi)));
  const bool log_y = emin > 0 && emax > 10 * emin;
  const double e0 = log_y ? std::floor(std::log10(emin)) : 0.0;
  const double e1 = log_y ? std::ceil(std::log10(emax)) : (emax > 0 ? 1.1 * emax : 1.0);
  auto X = [&](double ms) { return px + (std::log10(ms) - d0) / (d1 - d0) * w; };
  auto Y = [&](double e) { return py + h - (log_y ? (std::log10(e) - e0) / (e1 - e0) : e / e1) * h; };
  auto tick_label = [&](double x, double y, const std::string& text, const char* anchor) {
    svg << "<text x=\"" << fmt(x) << "\" y=\"" << fmt(y) << "\" text-anchor=\"" << anchor << "\" font-size=\"11\">" << text
        << "</text>\n";
  };
  for (double d = d0; d <= d1; ++d) {
    const double x = X(std::pow(10, d));
    svg << "<line x1=\"" << fmt(x) << "\" y1=\"" << fmt(py + h) << "\" x2=\"" << fmt(x) << "\" y2=\"" << fmt(py + h + 5)
        << "\" stroke=\"#444\"/>\n";
    tick_label(x, py + h + 18, fmt(std::pow(10, d), "%g"), "middle");
  }
  const int y_ticks = log_y ? static_cast<int>(e1 - e0) : 4;
  for (int t = 0; t <= y_ticks; ++t) {
    const double e = log_y ? std::pow(10, e0 + t) : e1 * t / y_ticks;
    tick_label(px - 6, Y(e) + 4, fmt(e, "%.3g"), "end");
  }
  if (log_y) tick_label(px + 4, py - 4, "error: log scale", "start");
  svg << "<text x=\"" << fmt(px + w / 2) << "\" y=\"" << fmt(py + h + 38)
      << "\" text-anchor=\"middle\" font-size=\"12\">time per frame (ms, log scale)</text>\n";

  const std::vector<std::size_t> front = pareto_front(points);
  svg << "<polyline class=\"front\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\" points=\"";
  for (std::size_t i : front) svg << fmt(X(points[i].ms)) << "," << fmt(Y(points[i].error)) << " ";
  svg << "\"/>\n";
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool on_front = std::find(front.begin(), front.end(), i) != front.end();
    const BenchSetting& s = kept[i]->setting;
    std::string label = s.label();
    if (s.preset) label += " [" + std::string(shading::quality_name(*s.preset)) + "]";
    svg << "<circle cx=\"" << fmt(X(points[i].ms)) << "\" cy=\"" << fmt(Y(points[i].error)) << "\" r=\"3.5\" fill=\""
        << (on_front ? "#d62728" : "#7f7f7f") << "\"><title>" << xml_escape(label) << ": " << fmt(points[i].ms, "%.3g")
        << " ms, " << fmt(points[i].error, "%.4g") << "</title></circle>\n";
    // Labels of points in the right third run leftwards, to stay inside the panel.
    const bool right = X(points[i].ms) > px + 0.66 * w;
    if (on_front || s.preset)
      svg << "<text x=\"" << fmt(X(points[i].ms) + (right ? -5 : 5)) << "\" y=\"" << fmt(Y(points[i].error) - 5)
          << "\" font-size=\"9\"" << (right ? " text-anchor=\"end\"" : "") << ">" << xml_escape(label)
          << "</text>\n";
  }
  svg << "</g>\n";
}

}  // namespace

std::vector<std::size_t> pareto_front(const std::vector<PlotPoint>& points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a].ms != points[b].ms ? points[a].ms < points[b].ms : points[a].error < points[b].error;
  });
  std::vector<std::size_t> front;
  for (std::size_t i : order)
    if (front.empty() || points[i].error < points[front.back()].error) front.push_back(i);
  return front;
}

std::string pareto_svg(const std::vector<BenchRow>& rows) {
  // Scenes in order of appearance; a scene is (name, size).
  std::vector<std::pair<std::string, std::vector<const BenchRow*>>> scenes;
  std::vector<std::string> without_truth;
  for (const BenchRow& r : rows) {
    if (r.skipped) continue;  // not timed: no point
    const std::string key = r.scene + " " + r.size + " (" + r.backend + ", " + r.clock + " clock)";
    auto it = std::find_if(scenes.begin(), scenes.end(), [&](const auto& s) { return s.first == key; });
    if (it == scenes.end()) it = scenes.insert(scenes.end(), {key, {}});
    it->second.push_back(&r);
  }
  std::erase_if(scenes, [&](const auto& s) {
    const bool any = std::any_of(s.second.begin(), s.second.end(), [](const BenchRow* r) {
      return std::isfinite(r->shaded.rmse) || std::isfinite(r->skyview.rmse);
    });
    if (!any) without_truth.push_back(s.first);
    return !any;
  });
  const Series series[] = {{"shaded RMSE (8-bit code values)", [](const BenchRow& r) { return r.shaded.rmse; }},
                           {"skyview RMSE", [](const BenchRow& r) { return r.skyview.rmse; }}};
  const double note_h = without_truth.empty() && !scenes.empty() ? 0 : 24.0 * (1 + without_truth.size());
  const double width = 2 * kPanelW, height = kPanelH * scenes.size() + note_h + 8;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << fmt(width, "%.0f") << "\" height=\""
      << fmt(height, "%.0f") << "\" viewBox=\"0 0 " << fmt(width, "%.0f") << " " << fmt(height, "%.0f")
      << "\" font-family=\"sans-serif\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (std::size_t i = 0; i < scenes.size(); ++i)
    for (int c = 0; c < 2; ++c)
      draw_panel(svg, c * kPanelW, i * kPanelH, scenes[i].first, scenes[i].second, series[c]);
  double y = kPanelH * scenes.size() + 20;
  if (scenes.empty()) svg << "<text x=\"12\" y=\"" << fmt(y) << "\">no scene has ground truth</text>\n", y += 24;
  for (const auto& s : without_truth)
    svg << "<text x=\"12\" y=\"" << fmt(y) << "\" font-size=\"12\">" << xml_escape(s)
        << ": no ground truth (side above --truth-max-size), errors NA</text>\n", y += 24;
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace skylit::app::bench
