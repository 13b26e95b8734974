#include "visibility/direction_window.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "sphere/d3.h"

namespace gvm {
namespace {

using namespace sphere;  // D3

// Two unit vectors orthogonal to the unit vector u and to each other.
std::array<D3, 2> orthonormal_to(const D3& u) {
  const D3 helper = std::fabs(u[0]) < 0.6 ? D3{1, 0, 0} : D3{0, 1, 0};
  const D3 n1 = normalized(cross(u, helper));
  return {n1, cross(u, n1)};
}

// Whether q_max[k] - p_min[k] < bound for some k in [begin, end). A pair that meets the
// cell reads every side, 420 of them on a pocket floor: in blocks of eight, compared as
// vectors (GCC's vector extension, plain SSE2 on x86-64).
bool some_side_separates(const double* q_max, const double* p_min, size_t begin, size_t end, double bound) {
  using V2 = double __attribute__((vector_size(16)));
  using M2 = long __attribute__((vector_size(16)));
  auto load = [](const double* x) {
    V2 v;
    std::memcpy(&v, x, sizeof v);
    return v;
  };
  const V2 b = {bound, bound};
  size_t k = begin;
  for (; k + 8 <= end; k += 8) {
    M2 any = (load(q_max + k) - load(p_min + k)) < b;
    for (size_t i = 2; i < 8; i += 2) any |= (load(q_max + k + i) - load(p_min + k + i)) < b;
    if (any[0] | any[1]) return true;
  }
  for (; k < end; ++k) {
    if (q_max[k] - p_min[k] < bound) return true;
  }
  return false;
}

}  // namespace

// m . x, the same double wherever a row is built.
double DirectionWindow::value(const D3& m, const Point3& x) { return m[0] * x[0] + m[1] * x[1] + m[2] * x[2]; }

DirectionWindow::InnerCap DirectionWindow::inscribed_cap(std::span<const D3> normals) {
  D3 sum{0, 0, 0};
  for (const D3& m : normals) sum = add(sum, m);
  if (!(norm(sum) > 1e-9)) return {};  // a point's or an arc's cell has no inside
  const D3 c = normalized(sum);
  // m . c >= sin r for every side m puts the cap of radius r around c inside the cell.
  double sin_radius = 1;
  for (const D3& m : normals) sin_radius = std::min(sin_radius, dot(m, c));
  if (!(sin_radius > 1e-3)) return {};
  // The margin takes more than 2e-12 off the cap's cos^2 r = 1 - sin^2 r, far above the
  // rounding of holds(), relative 1e-15.
  sin_radius -= 1e-9;
  return {c, 1 - sin_radius * sin_radius};
}

bool DirectionWindow::InnerCap::holds(const D3& x, double norm2_x) const {
  const double d = dot(centre, x);
  return d > 0 && d * d > cos2_radius * norm2_x;
}

void DirectionWindow::end_cell() {
  const size_t begin = cell_end_.empty() ? 0 : cell_end_.back();
  inner_.push_back(inscribed_cap(std::span(normals_).subspan(begin)));
  cell_end_.push_back(normals_.size());
}

void DirectionWindow::add_half_spaces(const sphere::Face& convex) {
  for (const sphere::Loop& loop : convex.loops) {
    for (const sphere::Arc& arc : loop.arcs) normals_.push_back(arc.normal.unit());
  }
}

DirectionWindow::DirectionWindow(double coordinate_bound)
    // Each value m . q is off by about 1e-15 * coordinate_bound (rounding, and m being a
    // rounded unit vector); the slack is far above that and far below any real margin.
    : slack_(1e-9 * coordinate_bound) {}

DirectionWindow::DirectionWindow(const sphere::SphericalImage& lvm, double coordinate_bound)
    : DirectionWindow(coordinate_bound) {
  if (lvm.is_full_sphere()) return;
  // A convex 2-cell is the intersection of the hemispheres of its arcs.
  for (const sphere::Face& f : lvm.faces()) {
    add_half_spaces(f);
    end_cell();
  }
  add_lower_dimensional(lvm);
}

void DirectionWindow::add_lower_dimensional(const sphere::SphericalImage& set) {
  // An arc lies on its circle and, when shorter than 180 degrees, on the forward side of
  // its start and the backward side of its end.
  for (const sphere::Arc& arc : set.curves()) {
    const D3 n = arc.normal.unit();
    normals_.push_back(n);
    normals_.push_back(negated(n));
    if (!arc.full) {
      const D3 a = arc.start.unit(), b = arc.end.unit();
      const D3 axb = cross(a, b);
      if (axb[0] * n[0] + axb[1] * n[1] + axb[2] * n[2] > 1e-6) {
        normals_.push_back(normalized(cross(n, a)));
        normals_.push_back(normalized(cross(b, n)));
      }
    }
    end_cell();
  }
  // A point lies on two orthogonal circles through it and in its own hemisphere.
  for (const exact::ExactVec& p : set.points()) {
    const D3 u = p.unit();
    const auto [n1, n2] = orthonormal_to(u);
    for (const D3& m : {n1, negated(n1), n2, negated(n2), u}) normals_.push_back(m);
    end_cell();
  }
}

void DirectionWindow::add_cap(const D3& centre, double radius, const sphere::Face& within) {
  // For t orthogonal to the centre c, m = sin(r) c - cos(r) t gives m . x >= 0 for every x
  // within r of c: m . x >= sin(r) cos(r) - cos(r) sin(r) = 0.
  const auto [t1, t2] = orthonormal_to(centre);
  const double s = std::sin(radius), c = std::cos(radius);
  for (const D3& t : {t1, negated(t1), t2, negated(t2)}) {
    normals_.push_back(normalized(add(D3{s * centre[0], s * centre[1], s * centre[2]}, t, -c)));
  }
  add_half_spaces(within);
  end_cell();
}

std::optional<DirectionWindow> DirectionWindow::covering(const sphere::SphericalImage& set,
                                                         const sphere::Face& within, double coordinate_bound) {
  if (set.is_full_sphere()) return std::nullopt;
  DirectionWindow window(coordinate_bound);
  // The estimates are within 1e-15 of the exact directions and the normals' rounding moves
  // the half-spaces by as little: a margin of 1e-7 radians covers both.
  constexpr double kMargin = 1e-7, kLargest = 1.5;  // radians; 1.5 < pi / 2
  for (const sphere::Face& f : set.faces()) {
    std::vector<D3> corners;
    for (const sphere::Loop& loop : f.loops) {
      for (const sphere::Arc& arc : loop.arcs) {
        // Only arcs certainly shorter than 180 degrees stay in a cap with their ends.
        const exact::UnitEstimate a = exact::unit_estimate(arc.start), b = exact::unit_estimate(arc.end);
        if (arc.full || !(a.radius < 1e-12 && b.radius < 1e-12)) return std::nullopt;
        if (!(dot(cross(a.unit, b.unit), arc.normal.unit()) > 1e-9)) return std::nullopt;
        corners.push_back(a.unit);
      }
    }
    D3 sum{0, 0, 0};
    for (const D3& x : corners) sum = add(sum, x);
    if (!(norm(sum) > 1e-3)) return std::nullopt;
    const D3 centre = normalized(sum);
    double radius = 0;
    for (const D3& x : corners) radius = std::max(radius, std::atan2(norm(cross(centre, x)), dot(centre, x)));
    radius += kMargin;
    if (!(radius < kLargest)) return std::nullopt;
    // The boundary lies in the cap (each arc is shorter than 180 degrees and the cap is
    // convex), so the face is the cap's inside or holds everything outside it, the
    // antipode of its centre included.
    if (sphere::face_contains(f, exact::ExactVec::from_point({-centre[0], -centre[1], -centre[2]}))) {
      return std::nullopt;
    }
    window.add_cap(centre, radius, within);
  }
  window.add_lower_dimensional(set);
  return window;
}

void DirectionWindow::values(const Point3& x, double* out) const {
  if (normals_.empty()) return;
  const size_t K = normals_.size();
  for (size_t k = 0; k < K; ++k) out[k] = value(normals_[k], x);
  out[K] = x[0], out[K + 1] = x[1], out[K + 2] = x[2];
}

void DirectionWindow::fold(double* row, const double* values, bool largest) const {
  for (size_t k = 0; k < normals_.size(); ++k) {
    row[k] = largest ? std::max(row[k], values[k]) : std::min(row[k], values[k]);
  }
}

void DirectionWindow::row(const SolidMesh& mesh, std::initializer_list<uint32_t> vertices, bool largest,
                          double* out) const {
  if (normals_.empty()) return;
  const size_t K = normals_.size();
  for (size_t k = 0; k < K; ++k) {
    bool first = true;
    for (uint32_t v : vertices) {
      const double x = value(normals_[k], mesh.points[v]);
      out[k] = first ? x : largest ? std::max(out[k], x) : std::min(out[k], x);
      first = false;
    }
  }
  const Point3& anchor = mesh.points[*vertices.begin()];
  out[K] = anchor[0], out[K + 1] = anchor[1], out[K + 2] = anchor[2];
}

double coordinate_bound(const SolidMesh& mesh, std::span<const uint32_t> a,
                        std::span<const uint32_t> b) {
  double bound = 0;
  for (auto triangles : {a, b}) {
    for (uint32_t t : triangles) {
      for (uint32_t v : mesh.triangles[t]) {
        const Point3& p = mesh.points[v];
        bound = std::max({bound, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
      }
    }
  }
  return bound;
}

std::vector<double> DirectionWindow::extremes(const SolidMesh& mesh,
                                             std::span<const uint32_t> triangles,
                                             bool largest) const {
  const size_t R = row_size();
  std::vector<double> out(triangles.size() * R);
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Triangle& t = mesh.triangles[triangles[i]];
    row(mesh, {t[0], t[1], t[2]}, largest, &out[i * R]);
  }
  return out;
}

bool DirectionWindow::may_meet(const double* q_max, const double* p_min) const {
  if (normals_.empty()) return true;  // the window holds every direction
  const size_t K = normals_.size();
  // The anchors' difference is a direction of the face (up to rounding far below the caps'
  // margin): in a cell's inner cap, it shows that no side of the cell separates the face.
  const D3 x{q_max[K] - p_min[K], q_max[K + 1] - p_min[K + 1], q_max[K + 2] - p_min[K + 2]};
  const double norm2_x = dot(x, x);
  size_t begin = 0;
  for (size_t c = 0; c < cell_end_.size(); ++c) {
    const size_t end = cell_end_[c];
    if (inner_[c].holds(x, norm2_x)) return true;
    if (!some_side_separates(q_max, p_min, begin, end, -slack_)) return true;
    begin = end;
  }
  return false;
}

WindowRows::WindowRows(const DirectionWindow* window, size_t count, std::vector<double> rows, Side side)
    : window_(window), k_(window ? window->row_size() : 0), count_(count), side_(side), rows_(std::move(rows)) {
  if (k_ == 0) return;
  runs_.resize((count_ + kRun - 1) / kRun * k_);
  for (size_t i = 0; i < count_; ++i) {
    double* run = &runs_[i / kRun * k_];
    if (i % kRun == 0) {
      std::copy_n(row(i), k_, run);
    } else {
      window_->fold(run, row(i), side == Side::occluder);
    }
  }
}

}  // namespace gvm
