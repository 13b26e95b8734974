#include "snapshot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace gvm::report {
namespace {

using Vec3 = std::array<double, 3>;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 minus(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

// Screen axes, unit and right-handed: right x up = toward (out of the screen).
struct Frame {
  Vec3 right, up, toward;
};

std::optional<Frame> view_frame(const Vec3& toward_viewer) {
  const double length = std::sqrt(dot(toward_viewer, toward_viewer));
  if (!(length > 0) || !std::isfinite(length)) return std::nullopt;
  const Vec3 toward = scaled(toward_viewer, 1 / length);
  // +z up unless we look (nearly) along z, where its projection is tiny and would spin
  // the picture with small changes of the direction; then +y.
  const Vec3 reference = std::abs(toward[2]) > 0.999 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  const Vec3 up_raw = minus(reference, scaled(toward, dot(reference, toward)));
  const Vec3 up = scaled(up_raw, 1 / std::sqrt(dot(up_raw, up_raw)));
  return Frame{cross(up, toward), up, toward};
}

// A point on the screen: pixel coordinates (x right, y down) and depth (larger is nearer).
struct ScreenPoint {
  double x = 0, y = 0, depth = 0;
};

bool drawable(const std::array<uint32_t, 3>& t, std::span<const std::array<double, 3>> points) {
  for (uint32_t i : t) {
    if (i >= points.size()) return false;
    for (double c : points[i]) if (!std::isfinite(c)) return false;
  }
  return true;
}

// Projects the points used by drawable triangles and fits their bounding box into the
// image; nothing when there is nothing with an extent to draw.
std::optional<std::vector<ScreenPoint>> fitted(std::span<const std::array<double, 3>> points,
                                               std::span<const std::array<uint32_t, 3>> triangles,
                                               const Frame& frame, int size) {
  std::vector<ScreenPoint> screen(points.size());
  std::vector<bool> used(points.size(), false);
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (const auto& t : triangles) {
    if (!drawable(t, points)) continue;
    for (uint32_t i : t) {
      if (used[i]) continue;
      used[i] = true;
      screen[i] = {dot(points[i], frame.right), dot(points[i], frame.up), dot(points[i], frame.toward)};
      lo[0] = std::min(lo[0], screen[i].x), hi[0] = std::max(hi[0], screen[i].x);
      lo[1] = std::min(lo[1], screen[i].y), hi[1] = std::max(hi[1], screen[i].y);
    }
  }
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if (!(extent > 0) || !std::isfinite(extent)) return std::nullopt;
  const int margin = size / 25;
  const double scale = (size - 2 * margin) / extent, half = size / 2.0;
  const double cx = (lo[0] + hi[0]) / 2, cy = (lo[1] + hi[1]) / 2;
  for (size_t i = 0; i < screen.size(); ++i) {
    if (!used[i]) continue;
    screen[i].x = half + (screen[i].x - cx) * scale;
    screen[i].y = half - (screen[i].y - cy) * scale;  // rows go down, "up" goes up
  }
  return screen;
}

// The edge function of the line a-b at p, evaluated with the endpoints in a canonical
// order, so the two triangles sharing an edge get exactly opposite values there and no
// pixel centre on (or rounding-close to) a shared edge falls through both.
struct Edge {
  ScreenPoint from;
  double dx = 0, dy = 0, sign = 1;
  Edge(const ScreenPoint& a, const ScreenPoint& b) {
    const bool ordered = a.x < b.x || (a.x == b.x && a.y < b.y);
    from = ordered ? a : b;
    const ScreenPoint& to = ordered ? b : a;
    dx = to.x - from.x, dy = to.y - from.y, sign = ordered ? 1 : -1;
  }
  double at(double px, double py) const { return sign * (dx * (py - from.y) - dy * (px - from.x)); }
};

struct Buffers {
  int size;
  std::vector<double> depth;
  std::vector<int32_t> owner;  // the triangle seen at each pixel, -1 for background
};

void rasterize(int32_t triangle, const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c, Buffers& buf) {
  const Edge e_bc(b, c), e_ca(c, a), e_ab(a, b);
  // Orient so that the inside is where all edge functions are >= 0, whichever way it faces.
  const double orientation = e_ab.at(c.x, c.y) >= 0 ? 1 : -1;
  const int last = buf.size - 1;
  // Pixel (i, j) has its centre at (i + 0.5, j + 0.5).
  const int x0 = std::max(0, static_cast<int>(std::ceil(std::min({a.x, b.x, c.x}) - 0.5)));
  const int x1 = std::min(last, static_cast<int>(std::floor(std::max({a.x, b.x, c.x}) - 0.5)));
  const int y0 = std::max(0, static_cast<int>(std::ceil(std::min({a.y, b.y, c.y}) - 0.5)));
  const int y1 = std::min(last, static_cast<int>(std::floor(std::max({a.y, b.y, c.y}) - 0.5)));
  for (int j = y0; j <= y1; ++j) {
    for (int i = x0; i <= x1; ++i) {
      const double px = i + 0.5, py = j + 0.5;
      const double wa = orientation * e_bc.at(px, py), wb = orientation * e_ca.at(px, py),
                   wc = orientation * e_ab.at(px, py);
      const double total = wa + wb + wc;  // twice the area: 0 when seen edge-on
      if (wa < 0 || wb < 0 || wc < 0 || !(total > 0)) continue;
      const double depth = (wa * a.depth + wb * b.depth + wc * c.depth) / total;
      const size_t k = static_cast<size_t>(j) * buf.size + i;
      if (depth > buf.depth[k]) buf.depth[k] = depth, buf.owner[k] = triangle;
    }
  }
}

// The headlight: faces turned toward the viewer bright, faces seen at a grazing angle dim.
double headlight(const std::array<uint32_t, 3>& t, std::span<const std::array<double, 3>> points,
                 const Vec3& toward) {
  const Vec3 n = cross(minus(points[t[1]], points[t[0]]), minus(points[t[2]], points[t[0]]));
  const double length = std::sqrt(dot(n, n));
  return 0.35 + 0.65 * (length > 0 ? std::min(1.0, std::abs(dot(n, toward)) / length) : 1.0);
}

Rgb color_of(int32_t triangle, std::span<const Rgb> colors) {
  return static_cast<size_t>(triangle) < colors.size() ? colors[triangle] : Rgb{160, 160, 160};
}

bool same(const Rgb& a, const Rgb& b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

// A visible pixel whose left or upper neighbour shows another colour lies on a feature
// line; marking one side only keeps the line 1 px wide.
bool on_line(const Buffers& buf, std::span<const Rgb> colors, int i, int j) {
  const size_t k = static_cast<size_t>(j) * buf.size + i;
  const Rgb here = color_of(buf.owner[k], colors);
  const auto differs = [&](size_t n) { return buf.owner[n] >= 0 && !same(color_of(buf.owner[n], colors), here); };
  return (i > 0 && differs(k - 1)) || (j > 0 && differs(k - buf.size));
}

void shade(const Buffers& buf, std::span<const std::array<double, 3>> points,
           std::span<const std::array<uint32_t, 3>> triangles, std::span<const Rgb> colors, const Vec3& toward,
           Image& image) {
  int32_t lit = -1;  // neighbouring pixels mostly show the same triangle: light it once
  double light = 0;
  for (int j = 0; j < buf.size; ++j) {
    for (int i = 0; i < buf.size; ++i) {
      const size_t k = static_cast<size_t>(j) * buf.size + i;
      const int32_t t = buf.owner[k];
      if (t < 0) continue;
      if (t != lit) lit = t, light = headlight(triangles[t], points, toward);
      const double f = on_line(buf, colors, i, j) ? 0.6 * light : light;
      const Rgb c = color_of(t, colors);
      uint8_t* px = &image.rgba[4 * k];
      px[0] = static_cast<uint8_t>(c.r * f + 0.5);
      px[1] = static_cast<uint8_t>(c.g * f + 0.5);
      px[2] = static_cast<uint8_t>(c.b * f + 0.5);
      px[3] = 255;
    }
  }
}

}  // namespace

Image render_snapshot(std::span<const std::array<double, 3>> points,
                      std::span<const std::array<uint32_t, 3>> triangles, std::span<const Rgb> triangle_colors,
                      const SnapshotView& view) {
  if (view.size < 1) return {};
  const size_t pixels = static_cast<size_t>(view.size) * static_cast<size_t>(view.size);
  Image image{view.size, view.size, std::vector<uint8_t>(4 * pixels, 0)};
  const std::optional<Frame> frame = view_frame(view.toward_viewer);
  if (!frame) return image;
  const auto screen = fitted(points, triangles, *frame, view.size);
  if (!screen) return image;
  Buffers buf{view.size, std::vector<double>(pixels, -std::numeric_limits<double>::infinity()),
              std::vector<int32_t>(pixels, -1)};
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& tri = triangles[t];
    if (!drawable(tri, points)) continue;
    rasterize(static_cast<int32_t>(t), (*screen)[tri[0]], (*screen)[tri[1]], (*screen)[tri[2]], buf);
  }
  shade(buf, points, triangles, triangle_colors, frame->toward, image);
  return image;
}

}  // namespace gvm::report
