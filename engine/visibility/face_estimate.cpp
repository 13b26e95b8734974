#include "visibility/face_estimate.h"

#include <algorithm>
#include <cmath>

namespace gvm {
namespace {

using sphere::Box;
using sphere::D3;

// The box around a convex face: around its sides, and reaching an axis' pole where the
// pole may lie inside (there a coordinate peaks inside the face).
Box face_box(const FaceEstimate& f, const std::vector<exact::UnitEstimate>& v) {
  Box box = sphere::arc_box(v.back(), v[0]);
  for (size_t i = 0; i + 1 < v.size(); ++i) {
    const Box side = sphere::arc_box(v[i], v[i + 1]);
    for (int k = 0; k < 3; ++k) {
      box.lo[k] = std::min(box.lo[k], side.lo[k]);
      box.hi[k] = std::max(box.hi[k], side.hi[k]);
    }
  }
  for (int k = 0; k < 3; ++k) {
    for (const double pole : {-1.0, 1.0}) {
      bool may_hold = true;
      for (size_t j = 0; j < f.inward.size(); ++j) may_hold = may_hold && pole * f.inward[j][k] > -(kSlack + f.error[j]);
      if (may_hold) (pole < 0 ? box.lo[k] : box.hi[k]) = pole;
    }
  }
  return box;
}

}  // namespace

FaceEstimate estimate_face(const std::vector<exact::ExactVec>& face) {
  FaceEstimate f;
  std::vector<exact::UnitEstimate> v;
  for (const exact::ExactVec& x : face) {
    v.push_back(exact::unit_estimate(x));
    if (!(v.back().radius <= kRadius)) return f;
    f.u.push_back(v.back().unit);
  }
  for (size_t i = 0; i < f.u.size(); ++i) {
    const D3 c = sphere::cross(f.u[i], f.u[(i + 1) % f.u.size()]);
    const double length = sphere::norm(c);
    f.inward.push_back(length > 0 ? sphere::normalized(c) : D3{});
    f.error.push_back(length > 0 ? 8 * kRadius / length + 1e-15 : INFINITY);
  }
  for (size_t i = 1; i + 1 < f.u.size(); ++i) {
    f.area += sphere::norm(sphere::cross(sphere::add(f.u[i], f.u[0], -1), sphere::add(f.u[i + 1], f.u[0], -1))) / 2;
  }
  f.box = face_box(f, v);
  f.certain = true;
  return f;
}

}  // namespace gvm
