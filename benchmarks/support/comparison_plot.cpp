#include "support/comparison_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace gvm::bench {
namespace {

constexpr double kPanelWidth = 460, kPanelHeight = 340;
constexpr double kLeft = 72, kRight = 18, kTop = 70, kBottom = 52;
constexpr const char* kEnvelopeColour = "#1f77b4";
constexpr const char* kConvexColour = "#d62728";

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string format(const char* fmt, auto... args) {
  char buf[512];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

// Whole decades covering the positive values (at least one decade wide).
struct LogAxis {
  int low = 0, high = 1;

  static LogAxis covering(const std::vector<double>& values) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (double v : values) {
      if (v > 0) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    if (hi == 0) return {};
    LogAxis a{int(std::floor(std::log10(lo))), int(std::ceil(std::log10(hi)))};
    if (a.high == a.low) ++a.high;
    return a;
  }
  // Position in [0, 1] along the axis.
  double at(double v) const { return (std::log10(v) - low) / (high - low); }
};

struct Mark {
  double x, y;
  bool envelope;
};

// One panel; x0 is its left edge in the document.
void draw_panel(std::string& svg, double x0, const std::string& y_label,
                const std::vector<Mark>& marks) {
  std::vector<double> xs, ys;
  for (const Mark& m : marks) xs.push_back(m.x), ys.push_back(m.y);
  const LogAxis ax = LogAxis::covering(xs), ay = LogAxis::covering(ys);
  const double left = x0 + kLeft, top = kTop;
  const double w = kPanelWidth - kLeft - kRight, h = kPanelHeight - kTop - kBottom;
  auto px = [&](double v) { return left + ax.at(v) * w; };
  auto py = [&](double v) { return top + h - ay.at(v) * h; };

  svg += format("<rect x='%.1f' y='%.1f' width='%.1f' height='%.1f' fill='none' stroke='#444'/>\n",
                left, top, w, h);
  auto decade_label = [](int k) {
    return format("10<tspan dy='-6' font-size='9'>%d</tspan>", k);
  };
  for (int k = ax.low; k <= ax.high; ++k) {
    const double x = left + double(k - ax.low) / (ax.high - ax.low) * w;
    svg += format("<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#ddd'/>\n", x, top, x,
                  top + h);
    svg += format("<text x='%.1f' y='%.1f' text-anchor='middle'>%s</text>\n", x, top + h + 18,
                  decade_label(k).c_str());
  }
  for (int k = ay.low; k <= ay.high; ++k) {
    const double y = top + h - double(k - ay.low) / (ay.high - ay.low) * h;
    svg += format("<line x1='%.1f' y1='%.1f' x2='%.1f' y2='%.1f' stroke='#ddd'/>\n", left, y,
                  left + w, y);
    svg += format("<text x='%.1f' y='%.1f' text-anchor='end'>%s</text>\n", left - 6, y + 4,
                  decade_label(k).c_str());
  }
  svg += format("<text x='%.1f' y='%.1f' text-anchor='middle'>|S| &#183; |O_S| (triangles)</text>\n",
                left + w / 2, top + h + 42);
  svg += format("<text transform='translate(%.1f %.1f) rotate(-90)' text-anchor='middle'>%s</text>\n",
                x0 + 18, top + h / 2, escaped(y_label).c_str());
  // Convex first, so that the envelope's marks stay visible where they overlap.
  for (bool envelope : {false, true}) {
    for (const Mark& m : marks) {
      if (m.envelope != envelope || m.x <= 0 || m.y <= 0) continue;
      if (envelope) {
        svg += format("<circle cx='%.1f' cy='%.1f' r='3.5' fill='%s' fill-opacity='0.75'/>\n",
                      px(m.x), py(m.y), kEnvelopeColour);
      } else {
        svg += format("<rect x='%.1f' y='%.1f' width='7' height='7' fill='%s' fill-opacity='0.6'/>\n",
                      px(m.x) - 3.5, py(m.y) - 3.5, kConvexColour);
      }
    }
  }
}

}  // namespace

std::string comparison_plot_svg(const v1::Comparison& comparison) {
  using Value = std::function<double(const v1::MethodRun&)>;
  int left_out = 0;
  auto marks_of = [&](const Value& value) {
    std::vector<Mark> marks;
    for (const v1::SurfaceComparison& s : comparison.surfaces()) {
      const double pairs = double(s.s()) * s.o_s();
      for (bool envelope : {true, false}) {
        if (!envelope && !s.has_convex()) continue;
        const double v = value(envelope ? s.envelope() : s.convex());
        if (pairs > 0 && v > 0) {
          marks.push_back({pairs, v, envelope});
        } else {
          ++left_out;
        }
      }
    }
    return marks;
  };
  const auto seconds = marks_of([](const v1::MethodRun& r) { return r.seconds(); });
  const auto arrangement =
      marks_of([](const v1::MethodRun& r) { return double(r.arrangement_vertices()); });

  const double width = 2 * kPanelWidth, height = kPanelHeight + 24;
  std::string svg = format(
      "<svg xmlns='http://www.w3.org/2000/svg' width='%.0f' height='%.0f' "
      "viewBox='0 0 %.0f %.0f' font-family='sans-serif' font-size='12'>\n"
      "<rect width='100%%' height='100%%' fill='white'/>\n",
      width, height, width, height);
  svg += format(
      "<text x='%.1f' y='20' text-anchor='middle' font-size='14'>Effective Minkowski envelope "
      "against convex decomposition</text>\n"
      "<text x='%.1f' y='37' text-anchor='middle' font-size='11' fill='#444'>%d surfaces, "
      "%u thread(s), %s</text>\n",
      width / 2, width / 2, comparison.surfaces_size(), comparison.threads(),
      escaped(comparison.machine()).c_str());
  svg += format(
      "<circle cx='%.1f' cy='52' r='3.5' fill='%s'/><text x='%.1f' y='56'>envelope (EME)</text>\n"
      "<rect x='%.1f' y='48.5' width='7' height='7' fill='%s'/>"
      "<text x='%.1f' y='56'>convex decomposition</text>\n",
      kLeft + 8, kEnvelopeColour, kLeft + 16, kLeft + 130, kConvexColour, kLeft + 142);
  draw_panel(svg, 0, "seconds", seconds);
  draw_panel(svg, kPanelWidth, "#Arrng (arrangement vertices)", arrangement);
  if (left_out) {
    svg += format("<text x='%.1f' y='%.1f' font-size='10' fill='#666'>%d zero values left off the "
                  "log axes</text>\n",
                  kLeft, height - 6, left_out);
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace gvm::bench
