#include "sphere/spherical_image.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "sphere/d3.h"
#include "sphere/point_in_face.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;

constexpr double kPi = 3.14159265358979323846;

bool nonneg(Sign s) { return s != Sign::kNegative; }

ExactVec axis(int i) {
  return ExactVec::from_point({i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0});
}

// A direction on the great circle {u . c = 0} (c non-zero), an exact construction.
ExactVec point_on_circle(const ExactVec& c) {
  for (int i = 0; i < 3; ++i) {
    ExactVec p = cross(c, axis(i));
    if (!exact::is_zero(p)) return p;
  }
  return {};  // c is zero: unreachable for valid arcs
}

// The arc lies in the closed hemisphere {u . n >= 0}.
bool arc_within(const Arc& arc, const ExactVec& n) {
  if (exact::parallel(arc.normal, n)) return true;  // the whole circle has u . n = 0
  if (arc.full) return false;
  if (!nonneg(exact::sign_dot(arc.start, n)) || !nonneg(exact::sign_dot(arc.end, n))) return false;
  // Both ends are in the closed half circle {u . n >= 0}; the arc leaves it iff it passes
  // through w, the point of the circle where u . n is smallest (and negative).
  ExactVec w = cross(arc.normal, cross(arc.normal, n));
  return !arc_contains(arc, w);
}

bool arc_equal(const Arc& a, const Arc& b) {
  if (a.full != b.full) return false;
  if (a.full) return exact::parallel(a.normal, b.normal);
  if (exact::same_direction(a.normal, b.normal)) {
    return exact::same_direction(a.start, b.start) && exact::same_direction(a.end, b.end);
  }
  if (exact::same_direction(a.normal, -b.normal)) {
    return exact::same_direction(a.start, b.end) && exact::same_direction(a.end, b.start);
  }
  return false;
}

bool arc_identical(const Arc& a, const Arc& b) {
  if (a.full != b.full || !exact::same_direction(a.normal, b.normal)) return false;
  return a.full ||
         (exact::same_direction(a.start, b.start) && exact::same_direction(a.end, b.end));
}

std::vector<ExactVec> distinct_normals(const Face& f) {
  std::vector<ExactVec> out;
  for (const Loop& l : f.loops) {
    for (const Arc& a : l.arcs) {
      bool seen = false;
      for (const ExactVec& o : out) seen = seen || exact::same_direction(o, a.normal);
      if (!seen) out.push_back(a.normal);
    }
  }
  return out;
}

bool loop_equal(const Loop& a, const Loop& b) {
  size_t n = a.arcs.size();
  if (n != b.arcs.size()) return false;
  if (n == 0) return true;
  for (size_t r = 0; r < n; ++r) {
    bool ok = true;
    for (size_t i = 0; i < n && ok; ++i) ok = arc_identical(a.arcs[i], b.arcs[(i + r) % n]);
    if (ok) return true;
  }
  return false;
}

template <class T, class Eq>
bool match_one_to_one(const std::vector<T>& a, const std::vector<T>& b, Eq eq) {
  if (a.size() != b.size()) return false;
  std::vector<bool> used(b.size(), false);
  for (const T& x : a) {
    bool found = false;
    for (size_t j = 0; j < b.size() && !found; ++j) {
      if (!used[j] && eq(x, b[j])) used[j] = found = true;
    }
    if (!found) return false;
  }
  return true;
}

bool face_equal(const Face& a, const Face& b) {
  if (a.convex && b.convex) {
    auto na = distinct_normals(a), nb = distinct_normals(b);
    return match_one_to_one(na, nb, [](const ExactVec& x, const ExactVec& y) {
      return exact::same_direction(x, y);
    });
  }
  if (a.convex != b.convex) return false;
  return match_one_to_one(a.loops, b.loops, loop_equal);
}

// --- doubles, for output only ---


// Angle of the arc in radians, in the range fixed by the exact classification.
double arc_angle(const Arc& arc) {
  if (arc.full) return 2 * kPi;
  Sign s = exact::sign_det(arc.normal, arc.start, arc.end);
  if (s == Sign::kZero) return exact::same_direction(arc.start, arc.end) ? 0.0 : kPi;
  D3 a = arc.start.unit(), b = arc.end.unit(), c = arc.normal.unit();
  double t = std::atan2(dot(c, cross(a, b)), dot(a, b));
  if (s == Sign::kPositive) return std::clamp(t, 0.0, kPi);
  if (t < 0) t += 2 * kPi;
  return std::clamp(t, kPi, 2 * kPi);
}

// Gauss-Bonnet: area = 2 pi chi - sum of turning angles, chi = 2 - number of loops. The
// turning angles at the loops' vertices, from the unit vectors `unit` gives.
template <class Unit>
std::vector<double> turning_angles(const Face& f, const Unit& unit) {
  std::vector<double> angles;
  for (const Loop& l : f.loops) {
    size_t n = l.arcs.size();
    if (n == 1 && l.arcs[0].full) continue;
    for (size_t i = 0; i < n; ++i) {
      const Arc& in = l.arcs[i];
      const Arc& out = l.arcs[(i + 1) % n];
      D3 v = unit(out.start);
      D3 t_in = cross(unit(in.normal), v), t_out = cross(unit(out.normal), v);
      angles.push_back(std::atan2(dot(v, cross(t_in, t_out)), dot(t_in, t_out)));
    }
  }
  return angles;
}

double area_from(const Face& f, const std::vector<double>& angles) {
  double total = 2 * kPi * (2.0 - static_cast<double>(f.loops.size()));
  for (double a : angles) total -= a;
  return std::max(0.0, std::min(4 * kPi, total));
}

double face_area(const Face& f) {
  return area_from(f, turning_angles(f, [](const ExactVec& x) { return x.unit(); }));
}

// The same doubles for the same face however it was built: the angles from the nearest
// unit vectors (unit() depends on how a vector was constructed), summed in ascending
// order (not in the order of the loops, which start anywhere).
double canonical_face_area(const Face& f) {
  std::vector<double> angles = turning_angles(f, [](const ExactVec& x) { return x.nearest_unit(); });
  std::sort(angles.begin(), angles.end());
  return area_from(f, angles);
}

std::string fmt_num(double x, const char* f) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

std::string fmt_coord(double x) {
  std::string s = fmt_num(x, "%.4f");
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

std::string fmt_vec(const ExactVec& v) {
  D3 u = v.nearest_unit();  // the same text for one direction however it was built
  std::string s = "(";  // appended piecewise: GCC 12 warns falsely on "(" + std::string
  s += fmt_coord(u[0]);
  s += ", ";
  s += fmt_coord(u[1]);
  s += ", ";
  s += fmt_coord(u[2]);
  s += ")";
  return s;
}

std::string describe_face(const Face& f) {
  if (f.loops.size() == 1 && f.loops[0].arcs.size() == 1 && f.loops[0].arcs[0].full) {
    return "hemisphere around " + fmt_vec(f.loops[0].arcs[0].normal);
  }
  if (f.convex && f.loops.size() == 1 && f.loops[0].arcs.size() == 2) {
    const Arc& a = f.loops[0].arcs[0];
    const bool swap = a.end.nearest_unit() < a.start.nearest_unit();  // the corners in one order
    return "lune of " + fmt_num(canonical_face_area(f) / 2 * 180 / kPi, "%.1f") + " deg between " +
           fmt_vec(swap ? a.end : a.start) + " and " + fmt_vec(swap ? a.start : a.end);
  }
  size_t vertices = 0;
  for (const Loop& l : f.loops) vertices += l.arcs.size();
  std::string s = "polygon with " + std::to_string(vertices) + " vertices";
  if (f.loops.size() > 1) s += " and " + std::to_string(f.loops.size() - 1) + " holes";
  return s + ", " + fmt_num(canonical_face_area(f), "%.2f") + " sr";
}

std::string describe_curve(const Arc& a) {
  if (a.full) return "great circle around " + fmt_vec(a.normal);
  return "arc of " + fmt_num(arc_angle(a) * 180 / kPi, "%.1f") + " deg from " + fmt_vec(a.start) +
         " to " + fmt_vec(a.end);
}


}  // namespace

bool face_contains(const Face& f, const ExactVec& u) {
  if (!f.convex) return point_in_face(f, u);
  for (const Loop& l : f.loops) {
    for (const Arc& a : l.arcs) {
      if (!nonneg(exact::sign_dot(u, a.normal))) return false;
    }
  }
  return true;
}

bool arc_contains(const Arc& arc, const ExactVec& u) {
  if (exact::sign_dot(u, arc.normal) != Sign::kZero) return false;
  if (arc.full) return true;
  const ExactVec& c = arc.normal;
  Sign s = exact::sign_det(c, arc.start, arc.end);
  if (s == Sign::kPositive) {  // shorter than 180 degrees
    return nonneg(exact::sign_det(c, arc.start, u)) && nonneg(exact::sign_det(c, u, arc.end));
  }
  if (s == Sign::kZero) {
    if (exact::same_direction(arc.start, arc.end)) return exact::same_direction(u, arc.start);
    return nonneg(exact::sign_det(c, arc.start, u));  // exactly 180 degrees
  }
  // Longer than 180 degrees: not in the open complementary arc from end to start.
  return !(exact::sign_det(c, arc.end, u) == Sign::kPositive &&
           exact::sign_det(c, u, arc.start) == Sign::kPositive);
}

std::vector<ExactVec> split_arc(const Arc& arc) {
  const ExactVec& c = arc.normal;
  if (arc.full) {
    ExactVec p = point_on_circle(c);
    ExactVec q = cross(c, p);
    return {p, q, -p, -q, p};
  }
  Sign s = exact::sign_det(c, arc.start, arc.end);
  if (s == Sign::kPositive) return {arc.start, arc.end};
  if (s == Sign::kZero) {
    if (exact::same_direction(arc.start, arc.end)) return {arc.start, arc.end};
    return {arc.start, cross(c, arc.start), arc.end};
  }
  return {arc.start, cross(c, arc.start), -arc.start, arc.end};
}

std::vector<ExactVec> split_arc_quarters(const Arc& arc) {
  const ExactVec& c = arc.normal;
  if (arc.full) {
    ExactVec p = point_on_circle(c);
    ExactVec q = cross(c, p);
    return {p, q, -p, -q, p};
  }
  // The quarter points n x start, -start, -(n x start) that lie strictly before the end:
  // the end's quadrant, from the signs of its sine and cosine against the start.
  const Sign sine = exact::sign_det(c, arc.start, arc.end);
  const Sign cosine = exact::sign_dot(arc.start, arc.end);
  int quarters = 0;  // whole quarter turns strictly inside the arc
  if (sine == Sign::kPositive) {
    quarters = cosine == Sign::kNegative ? 1 : 0;  // (90, 180) : (0, 90]
  } else if (sine == Sign::kZero) {
    quarters = cosine == Sign::kNegative ? 1 : 0;  // 180 : a zero-length arc
  } else {
    quarters = cosine == Sign::kPositive ? 3 : 2;  // (270, 360) : (180, 270]
  }
  std::vector<ExactVec> out = {arc.start};
  const ExactVec turn = cross(c, arc.start);
  const ExactVec quarter_points[3] = {turn, -arc.start, -turn};
  for (int i = 0; i < quarters; ++i) out.push_back(quarter_points[i]);
  out.push_back(arc.end);
  return out;
}

SphericalImage SphericalImage::full_sphere() {
  SphericalImage s;
  s.full_ = true;
  return s;
}

SphericalImage SphericalImage::point(const ExactVec& p) {
  SphericalImage s;
  s.points_.push_back(p);
  return s;
}

SphericalImage SphericalImage::hemisphere(const ExactVec& n) {
  SphericalImage s;
  Face f;
  f.convex = true;
  f.loops.push_back(Loop{{Arc{{}, {}, n, true}}});
  s.faces_.push_back(std::move(f));
  return s;
}

SphericalImage SphericalImage::great_circle(const ExactVec& n) {
  SphericalImage s;
  s.curves_.push_back(Arc{{}, {}, n, true});
  return s;
}

int SphericalImage::dimension() const {
  if (full_ || !faces_.empty()) return 2;
  if (!curves_.empty()) return 1;
  if (!points_.empty()) return 0;
  return -1;
}

bool SphericalImage::contains(const ExactVec& u) const {
  if (full_) return true;
  for (const ExactVec& p : points_) {
    if (exact::same_direction(p, u)) return true;
  }
  for (const Arc& a : curves_) {
    if (arc_contains(a, u)) return true;
  }
  for (const Face& f : faces_) {
    if (face_contains(f, u)) return true;
  }
  return false;
}

double SphericalImage::area() const {
  if (full_) return 4 * kPi;
  double a = 0;
  for (const Face& f : faces_) a += face_area(f);
  return a;
}

double SphericalImage::canonical_area() const {
  if (full_) return 4 * kPi;
  std::vector<double> areas;
  for (const Face& f : faces_) areas.push_back(canonical_face_area(f));
  std::sort(areas.begin(), areas.end());
  double a = 0;
  for (double x : areas) a += x;
  return a;
}

bool SphericalImage::within_closed_hemisphere(const ExactVec& n) const {
  if (exact::is_zero(n)) return true;
  if (full_) return false;
  for (const ExactVec& p : points_) {
    if (!nonneg(exact::sign_dot(p, n))) return false;
  }
  for (const Arc& a : curves_) {
    if (!arc_within(a, n)) return false;
  }
  ExactVec minus_n = -n;
  for (const Face& f : faces_) {
    // With its boundary in the closed hemisphere, a closed region either lies in it or
    // covers the whole open opposite hemisphere, hence -n.
    for (const Loop& l : f.loops) {
      for (const Arc& a : l.arcs) {
        if (!arc_within(a, n)) return false;
      }
    }
    if (face_contains(f, minus_n)) return false;
  }
  return true;
}

bool operator==(const SphericalImage& a, const SphericalImage& b) {
  if (a.full_ || b.full_) return a.full_ == b.full_;
  return match_one_to_one(a.faces_, b.faces_, face_equal) &&
         match_one_to_one(a.curves_, b.curves_, arc_equal) &&
         match_one_to_one(a.points_, b.points_, [](const ExactVec& x, const ExactVec& y) {
           return exact::same_direction(x, y);
         });
}

std::string SphericalImage::description() const {
  if (full_) return "full sphere";
  // Each kind of cell in one order, whatever the order they were built in.
  std::vector<std::string> faces, curves;
  for (const Face& f : faces_) faces.push_back(describe_face(f));
  for (const Arc& a : curves_) curves.push_back(describe_curve(a));
  std::sort(faces.begin(), faces.end());
  std::sort(curves.begin(), curves.end());
  std::vector<std::string> parts = faces;
  parts.insert(parts.end(), curves.begin(), curves.end());
  // One or two points named, sorted by their nearest unit vectors (each computed once: a
  // few exact evaluations); more only counted.
  std::vector<std::pair<D3, size_t>> named;
  if (points_.size() <= 2) {
    for (size_t i = 0; i < points_.size(); ++i) named.emplace_back(points_[i].nearest_unit(), i);
    std::sort(named.begin(), named.end());
  }
  auto point = [&](size_t k) { return fmt_vec(points_[named[k].second]); };
  if (points_.size() == 1) {
    parts.push_back("point " + point(0));
  } else if (points_.size() == 2) {
    parts.push_back("points " + point(0) + " and " + point(1));
  } else if (!points_.empty()) {
    parts.push_back(std::to_string(points_.size()) + " points");
  }
  if (parts.empty()) return "empty";
  std::string s = parts[0];
  for (size_t i = 1; i < parts.size(); ++i) s += "; " + parts[i];
  return s;
}

}  // namespace gvm::sphere
