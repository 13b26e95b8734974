// Projected envelope faces in doubles, with bounds that make their tests certain: the
// occlusion culling's view of a face (occlusion_culling.h).
//
// Estimates of unit vertices are within kRadius of the exact directions (else the face is
// not `certain` and every test keeps it), inward side normals within their `error` of the
// exact ones (a side between vertices e apart turns by up to about 2 kRadius / e); dot
// products then err by far less than kSlack.
#pragma once

#include <vector>

#include "exact/exact_vec.h"
#include "sphere/box_tree.h"
#include "sphere/d3.h"

namespace gvm {

inline constexpr double kRadius = 1e-12;
inline constexpr double kSlack = 1e-9;

struct FaceEstimate {
  std::vector<sphere::D3> u, inward;  // unit vertices, inward unit side normals
  std::vector<double> error;          // of each inward normal
  sphere::Box box{};                  // holds the closed face
  double area = 0;                    // of the planar polygon through u (a measure of size)
  bool certain = false;
};

// `face`: the vertices of a projected face, a convex polygon counter-clockwise around its
// inside, inside an open hemisphere.
FaceEstimate estimate_face(const std::vector<exact::ExactVec>& face);

// Whether x certainly lies inside the face, away from its sides.
inline bool strictly_inside(const FaceEstimate& f, const sphere::D3& x) {
  for (size_t j = 0; j < f.inward.size(); ++j) {
    if (!(sphere::dot(f.inward[j], x) > kSlack + f.error[j])) return false;
  }
  return true;
}

}  // namespace gvm
