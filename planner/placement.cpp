#include "placement.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gvm::planner {
namespace {

using Vec = std::array<double, 3>;

constexpr double kDegree = 0.017453292519943295;

double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec normalized(const Vec& v) {
  const double n = std::sqrt(dot(v, v));
  return {v[0] / n, v[1] / n, v[2] / n};
}

// Compass search on the sphere: from u, tries twelve tangent steps of size h (rotated by
// the golden angle each round, so that ridges of the min() are crossed), moves to the
// best improvement, halves h when there is none. `project` maps trial points onto the
// set the search is confined to.
template <class F, class P>
Vec climb(const F& f, const P& project, Vec u, int budget) {
  double fu = f(u), h = 0.25, turn = 0;
  for (int evals = 1; h > 1e-10 && evals < budget;) {
    const Vec a = std::fabs(u[0]) < 0.6 ? Vec{1, 0, 0} : Vec{0, 1, 0};
    const Vec t1 = normalized(cross(u, a)), t2 = cross(u, t1);
    Vec best = u;
    double f_best = fu;
    for (int k = 0; k < 12; ++k, ++evals) {
      const double phi = turn + k * (2 * M_PI / 12);
      const double c = h * std::cos(phi), s = h * std::sin(phi);
      const Vec v = project(normalized({u[0] + c * t1[0] + s * t2[0], u[1] + c * t1[1] + s * t2[1],
                                        u[2] + c * t1[2] + s * t2[2]}));
      const double fv = f(v);
      if (fv > f_best) f_best = fv, best = v;
    }
    if (f_best > fu) {
      u = best, fu = f_best;
    } else {
      h /= 2;
    }
    turn += 2.399963229728653;
  }
  return u;
}

}  // namespace

// Rounded up far enough to cover the rounding of the angle, of sin and of the square (a
// few ulps each).
double sin2_at_least(double degrees) {
  const double s = std::sin(degrees * kDegree);
  return std::min(1.0, s * s * (1 + 0x1p-46));
}

double approx_clearance(std::span<const DirectionSet* const> members, const Vec& u) {
  double m = std::numeric_limits<double>::infinity();
  for (const DirectionSet* s : members) m = std::min(m, s->approx_signed_clearance(u));
  return m;
}

double certified_clearance_degrees(const DirectionSet& set, const Direction& d, double estimate) {
  if (set.is_full_sphere()) return 180;
  if (set.dimension() < 2) return 0;
  // The largest whole number of micro-degrees whose cap fits, by bisection (caps are
  // nested, so the test is monotone): a requirement such as 5 degrees is met exactly
  // when its own cap fits.
  auto fits = [&](int64_t micro) { return set.contains_cap(d, sin2_at_least(double(micro) / 1e6)); };
  int64_t hi = static_cast<int64_t>(std::floor(std::min(90.0, estimate / kDegree) * 1e6));
  if (hi <= 0) return 0;
  if (fits(hi)) return double(hi) / 1e6;
  int64_t lo = 0;  // fits: the point itself is in the set
  while (hi - lo > 1) {
    const int64_t mid = lo + (hi - lo) / 2;
    (fits(mid) ? lo : hi) = mid;
  }
  return double(lo) / 1e6;
}

Placement place_in(std::span<const DirectionSet* const> members, const Direction& start) {
  std::vector<const DirectionSet*> wide, thin;  // with 2-cells; arcs and points only
  for (const DirectionSet* s : members) (s->dimension() == 2 ? wide : thin).push_back(s);
  auto f = [&](const Vec& u) { return approx_clearance(wide, u); };

  Direction d = start;
  if (thin.empty()) {
    const Vec u = climb(f, [](const Vec& v) { return v; }, start.unit(), 600);
    const Direction moved(u[0], u[1], u[2]);
    if (std::all_of(wide.begin(), wide.end(), [&](const DirectionSet* s) { return s->contains(moved); })) {
      d = moved;
    }
  } else {
    // On the arcs and points every thin member shares: exact directions of that set.
    DirectionSet on = *thin.front();
    for (size_t i = 1; i < thin.size(); ++i) on = on.intersection(*thin[i]);
    auto project = [&](const Vec& v) { return on.snap(v).unit(); };
    const Direction moved = on.snap(climb(f, project, start.unit(), 200));
    if (std::all_of(wide.begin(), wide.end(), [&](const DirectionSet* s) { return s->contains(moved); })) {
      d = moved;
    }
  }
  return placement_at(members, d);
}

Placement placement_at(std::span<const DirectionSet* const> members, const Direction& d) {
  Placement out{d, {}, {}};
  for (const DirectionSet* s : members) {
    const double c = certified_clearance_degrees(*s, d, s->approx_signed_clearance(d.unit()));
    out.clearance_degrees.push_back(c);
    out.exact_alignment.push_back(c == 0);
  }
  return out;
}

}  // namespace gvm::planner
