// Convex spherical polygons and brute-force membership, independently of the engine:
// winding numbers by crossings counted in doubles along a path, sample directions. For
// tests of regions built from polygons (positive regions, unions, clipping).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "sphere/arrangement.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere::test_polygons {

using exact::ExactVec;
using D3 = std::array<double, 3>;
using Polygon = std::vector<ExactVec>;  // convex, counter-clockwise seen from outside

inline constexpr double kPi = 3.14159265358979323846;

inline ExactVec v(double x, double y, double z) { return ExactVec::from_point({x, y, z}); }
inline ExactVec v(const D3& d) { return ExactVec::from_point({d[0], d[1], d[2]}); }

inline D3 cross_d(const D3& a, const D3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double dot_d(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline D3 unit_d(const D3& a) {
  const double n = std::sqrt(dot_d(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}
inline D3 axpy(double s, const D3& a, const D3& b) {
  return {s * a[0] + b[0], s * a[1] + b[1], s * a[2] + b[2]};
}

inline Polygon square(double x0, double y0, double x1, double y1, double z = 8) {
  return {v(x0, y0, z), v(x1, y0, z), v(x1, y1, z), v(x0, y1, z)};
}

inline void add_polygon(std::vector<ArrangementArc>& arcs, const Polygon& p, int weight = 1) {
  for (size_t i = 0; i < p.size(); ++i) {
    const ExactVec& a = p[i];
    const ExactVec& b = p[(i + 1) % p.size()];
    arcs.push_back({a, b, exact::cross(a, b), 0, weight});
  }
}

inline std::vector<ArrangementArc> arcs_of(const std::vector<Polygon>& polys) {
  std::vector<ArrangementArc> arcs;
  for (const Polygon& p : polys) add_polygon(arcs, p);
  return arcs;
}

// Brute force: u strictly inside a convex polygon iff strictly left of all its edges.
inline bool inside_polygon(const Polygon& p, const ExactVec& u) {
  for (size_t i = 0; i < p.size(); ++i) {
    if (exact::sign_det(p[i], p[(i + 1) % p.size()], u) != Sign::kPositive) return false;
  }
  return true;
}

inline int covering(const std::vector<Polygon>& polys, const ExactVec& u) {
  int n = 0;
  for (const Polygon& p : polys) n += inside_polygon(p, u);
  return n;
}

// A region's boundary in doubles.
struct DArc {
  D3 from, to, normal;
};

inline std::vector<DArc> to_doubles(const std::vector<ArrangementArc>& arcs) {
  std::vector<DArc> out;
  for (const ArrangementArc& a : arcs) out.push_back({a.from.unit(), a.to.unit(), a.normal.unit()});
  return out;
}

inline constexpr double kTol = 1e-9;

// Directions within kTol of one of the great circles are not sampled.
inline bool near_a_circle(const std::vector<DArc>& arcs, const D3& u) {
  for (const DArc& a : arcs) {
    if (std::fabs(dot_d(a.normal, u)) < kTol) return true;
  }
  return false;
}

// Winding number at u of the boundary arcs (weight 1, region on the left), independently
// of the engine: `base` at r plus the signed crossings of the minor arc from r to u.
// Nothing when the path comes within kTol of an arc endpoint's circle, of a crossing at
// its own ends, or when u is (nearly) r or -r.
inline std::optional<int> winding(const std::vector<DArc>& boundary, const D3& r, const D3& u,
                           int base) {
  const D3 ru = cross_d(r, u);
  const double len = std::sqrt(dot_d(ru, ru));
  if (len < 1e-6) return std::nullopt;
  const D3 n1 = {ru[0] / len, ru[1] / len, ru[2] / len};
  int w = base;
  for (const DArc& a : boundary) {
    const double sa = dot_d(n1, a.from), sb = dot_d(n1, a.to);
    if (std::fabs(sa) < kTol || std::fabs(sb) < kTol) return std::nullopt;
    if ((sa > 0) == (sb > 0)) continue;  // the (minor) arc does not reach the path circle
    // Where the chord from -> to meets the plane of the path: on the arc.
    const double t = sa / (sa - sb);
    const D3 p = unit_d(axpy(t, {a.to[0] - a.from[0], a.to[1] - a.from[1], a.to[2] - a.from[2]},
                             a.from));
    const double after_r = dot_d(cross_d(r, p), n1), before_u = dot_d(cross_d(p, u), n1);
    if (std::fabs(after_r) < kTol || std::fabs(before_u) < kTol) return std::nullopt;
    if (after_r < 0 || before_u < 0) continue;  // crosses the circle outside the path
    w += dot_d(a.normal, u) > 0 ? 1 : -1;
  }
  return w;
}

// Sample directions: a deterministic grid around +z (where the polygons are), a
// latitude-longitude grid and random directions, both uniform and near +z.
inline std::vector<D3> samples(uint64_t seed, int random_count = 1500) {
  std::vector<D3> out;
  for (double x = -9.3; x <= 9.3; x += 0.29) {
    for (double y = -9.1; y <= 9.1; y += 0.31) out.push_back(unit_d({x, y, 8}));
  }
  for (int i = 1; i < 30; ++i) {
    const double theta = kPi * i / 30;
    for (int j = 0; j < 40; ++j) {
      const double phi = 2 * kPi * (j + 0.37) / 40;
      out.push_back({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                     std::cos(theta)});
    }
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> near(-10, 10);
  for (int i = 0; i < random_count; ++i) {
    out.push_back(unit_d({g(rng), g(rng), g(rng)}));
    out.push_back(unit_d({near(rng), near(rng), 8}));
  }
  return out;
}

// Counter-clockwise triangle (seen from outside) of about the given size around (cx, cy, 8):
// corners at random angles, at `radius` times a random factor in [min_spread, 1).
inline Polygon triangle_around(std::mt19937_64& rng, double cx, double cy, double radius,
                               double min_spread = 0.6) {
  std::uniform_real_distribution<double> angle(0, 2 * kPi), spread(min_spread, 1.0);
  double a[3];
  for (double& t : a) t = angle(rng);
  std::sort(a, a + 3);
  Polygon p;
  for (double t : a) {
    const double r = radius * spread(rng);
    p.push_back(v(cx + r * std::cos(t), cy + r * std::sin(t), 8));
  }
  if (exact::sign_det(p[0], p[1], p[2]) != Sign::kPositive) std::swap(p[1], p[2]);
  return p;
}

// Random counter-clockwise triangle around +z (vertices on the plane z = 8).
inline Polygon random_triangle(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> centre(-3, 3), radius(0.7, 3), angle(0, 2 * kPi);
  const double cx = centre(rng), cy = centre(rng);
  double a[3];
  for (double& t : a) t = angle(rng);
  std::sort(a, a + 3);  // increasing angles: counter-clockwise seen from +z (outside)
  Polygon p;
  for (double t : a) {
    const double rr = radius(rng);
    p.push_back(v(cx + rr * std::cos(t), cy + rr * std::sin(t), 8));
  }
  if (exact::sign_det(p[0], p[1], p[2]) != Sign::kPositive) std::swap(p[1], p[2]);
  return p;
}

// A convex polygon as the closed image it bounds.
inline SphericalImage image_of(const Polygon& p) {
  Loop loop;
  for (size_t i = 0; i < p.size(); ++i) {
    const ExactVec &a = p[i], &b = p[(i + 1) % p.size()];
    loop.arcs.push_back({a, b, exact::cross(a, b)});
  }
  SphericalImage out;
  out.add_face({{std::move(loop)}, true});
  return out;
}

}  // namespace gvm::sphere::test_polygons
