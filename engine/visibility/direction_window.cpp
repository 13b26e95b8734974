#include "visibility/direction_window.h"

#include <algorithm>
#include <cmath>

#include "sphere/d3.h"

namespace gvm {
namespace {

using namespace sphere;  // D3

}  // namespace

DirectionWindow::DirectionWindow(const sphere::SphericalImage& lvm, double coordinate_bound)
    // Each value m . q is off by about 1e-15 * coordinate_bound (rounding, and m being a
    // rounded unit vector); the slack is far above that and far below any real margin.
    : slack_(1e-9 * coordinate_bound) {
  if (lvm.is_full_sphere()) return;
  auto end_cell = [&] { cell_end_.push_back(normals_.size()); };
  // A convex 2-cell is the intersection of the hemispheres of its arcs.
  for (const sphere::Face& f : lvm.faces()) {
    for (const sphere::Loop& loop : f.loops) {
      for (const sphere::Arc& arc : loop.arcs) normals_.push_back(arc.normal.unit());
    }
    end_cell();
  }
  // An arc lies on its circle and, when shorter than 180 degrees, on the forward side of
  // its start and the backward side of its end.
  for (const sphere::Arc& arc : lvm.curves()) {
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
  for (const exact::ExactVec& p : lvm.points()) {
    const D3 u = p.unit();
    const D3 helper = std::fabs(u[0]) < 0.6 ? D3{1, 0, 0} : D3{0, 1, 0};
    const D3 n1 = normalized(cross(u, helper)), n2 = cross(u, n1);
    for (const D3& m : {n1, negated(n1), n2, negated(n2), u}) normals_.push_back(m);
    end_cell();
  }
}

void DirectionWindow::values(const Point3& x, double* out) const {
  for (size_t k = 0; k < normals_.size(); ++k) {
    const D3& m = normals_[k];
    out[k] = m[0] * x[0] + m[1] * x[1] + m[2] * x[2];
  }
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
  const size_t K = size();
  std::vector<double> out(triangles.size() * K), v(K);
  for (size_t i = 0; i < triangles.size(); ++i) {
    double* e = &out[i * K];
    for (int j = 0; j < 3; ++j) {
      values(mesh.points[mesh.triangles[triangles[i]][j]], v.data());
      for (size_t k = 0; k < K; ++k) {
        e[k] = j == 0 ? v[k] : (largest ? std::max(e[k], v[k]) : std::min(e[k], v[k]));
      }
    }
  }
  return out;
}

bool DirectionWindow::may_meet(const double* q_max, const double* p_min) const {
  size_t begin = 0;
  for (size_t end : cell_end_) {
    bool separated = false;
    for (size_t k = begin; k < end && !separated; ++k) separated = q_max[k] - p_min[k] < -slack_;
    if (!separated) return true;
    begin = end;
  }
  return cell_end_.empty();
}

WindowRows::WindowRows(const DirectionWindow* window, size_t count, std::vector<double> rows, Side side)
    : window_(window), k_(window ? window->size() : 0), count_(count), side_(side), rows_(std::move(rows)) {
  if (k_ == 0) return;
  const bool largest = side == Side::occluder;
  runs_.assign((count_ + kRun - 1) / kRun * k_, largest ? -HUGE_VAL : HUGE_VAL);
  for (size_t i = 0; i < count_; ++i) {
    double* run = &runs_[i / kRun * k_];
    for (size_t k = 0; k < k_; ++k) run[k] = largest ? std::max(run[k], row(i)[k]) : std::min(run[k], row(i)[k]);
  }
}

}  // namespace gvm
