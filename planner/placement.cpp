#include "placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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
Vec climb(F& f, const P& project, Vec u, int budget) {
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

// The smallest signed clearance of many sets at a point, evaluated lazily: clearance is
// 1-Lipschitz in the angle, so a set whose last value, less the angle moved since, cannot
// undercut the minimum found so far is not evaluated again (most sets are far from the
// search, which moves in small steps).
class SmallestClearance {
 public:
  explicit SmallestClearance(std::span<const DirectionSet* const> sets)
      : sets_(sets.begin(), sets.end()), last_(sets.size(), -1e300), at_(sets.size(), Vec{0, 0, 0}),
        order_(sets.size()) {
    std::iota(order_.begin(), order_.end(), 0u);
  }

  double operator()(const Vec& u) {
    // The sets that were tightest last time first, so that the bound bites early.
    std::sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) { return last_[a] < last_[b]; });
    double smallest = std::numeric_limits<double>::infinity();
    for (uint32_t k : order_) {
      const double moved = std::acos(std::clamp(dot(at_[k], u), -1.0, 1.0));
      if (last_[k] > -1e299 && last_[k] - moved >= smallest) continue;
      last_[k] = sets_[k]->approx_signed_clearance(u);
      at_[k] = u;
      smallest = std::min(smallest, last_[k]);
    }
    return smallest;
  }

 private:
  std::vector<const DirectionSet*> sets_;
  std::vector<double> last_;
  std::vector<Vec> at_;
  std::vector<uint32_t> order_;
};

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

namespace {

// Where the search goes when some member is an arc or a point: on the directions every
// such member shares (their points tried one by one, their arcs searched along), exactly.
Direction on_thin_members(std::span<const DirectionSet* const> thin, SmallestClearance& f, const Direction& start) {
  DirectionSet on = *thin.front();
  for (size_t i = 1; i < thin.size(); ++i) on = on.intersection(*thin[i]);
  if (on.dimension() > 0) {
    auto project = [&](const Vec& v) { return on.snap(v).unit(); };
    return on.snap(climb(f, project, start.unit(), 200));
  }
  Direction best = start;
  double most = -std::numeric_limits<double>::infinity();
  for (const DirectionSet& point : on.cells()) {
    const Direction p = point.witness();
    const double c = f(p.unit());
    if (c > most) most = c, best = p;
  }
  return best;
}

}  // namespace

Placement place_in(std::span<const DirectionSet* const> members, const Direction& start) {
  std::vector<const DirectionSet*> wide, thin;  // with 2-cells; arcs and points only
  for (const DirectionSet* s : members) (s->dimension() == 2 ? wide : thin).push_back(s);
  SmallestClearance f(wide);
  Direction moved = start;
  if (thin.empty()) {
    const Vec u = climb(f, [](const Vec& v) { return v; }, start.unit(), 600);
    moved = Direction(u[0], u[1], u[2]);
  } else {
    moved = on_thin_members(thin, f, start);
  }
  // The search decides in doubles; the direction is kept only if every member holds it.
  const bool kept = std::all_of(wide.begin(), wide.end(), [&](const DirectionSet* s) { return s->contains(moved); });
  return placement_at(members, kept ? moved : start);
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
