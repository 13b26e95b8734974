// Where the pairwise maps of a pair of triangles cross one arc, in doubles with certain
// bounds: the occlusion probe leaves out the pairs whose crossing lies inside the
// crossings of others before it builds their exact maps.
//
// The directions q - p (q a corner of T, p a corner of F_S, q != p) span the cone over
// their convex hull P, and the pair's map is that cone on the sphere. The plane H of the
// arc meets the cone in the cone over P n H, spanned by the differences in H and by the
// points where the segment between a difference on one side of H and one on the other
// crosses it. When differences lie strictly on both sides and the triangles are not
// coplanar, H passes through the inside of the map, and the map's inside meets H in the
// open angular span between those points: what sphere::clip finds exactly. The signs
// are exact; the angles are doubles whose error is bounded per point.
#pragma once

#include <cstdint>
#include <vector>

#include "exact/exact_vec.h"
#include "gvm/mesh.h"
#include "sphere/d3.h"
#include "sphere/spherical_image.h"

namespace gvm {

// Angles along the circle of one arc shorter than 180 degrees, from its middle.
class ArcSpans {
 public:
  struct Span {
    enum class Kind : uint8_t {
      kMisses,   // the map's inside certainly misses the open arc
      kCrosses,  // the map's inside meets H in the open span (lo, hi), each end within error
      kUnknown,  // undecided in doubles: the exact map is needed
    };
    Kind kind = Kind::kUnknown;
    double lo = 0, hi = 0, error = 0;
  };

  explicit ArcSpans(const sphere::Arc& arc);

  // False when the arc is too long or its estimates too coarse for the doubles (every
  // pair is then kUnknown).
  bool usable() const { return usable_; }
  // The angles of the arc's ends, within kEndError of the exact ones.
  double start() const { return start_; }
  double end() const { return end_; }
  static constexpr double kEndError = 1e-9;

  Span of_pair(const SolidMesh& mesh, uint32_t fs, uint32_t ft) const;

  // The angle of a direction in the arc's plane, from the arc's middle towards its end.
  double angle(const sphere::D3& x) const;

 private:
  const sphere::Arc& arc_;
  sphere::D3 n_{}, e1_{}, e2_{};
  double normal_error_ = 0;
  double start_ = 0, end_ = 0;
  bool usable_ = false;
};

// The indices of the spans whose exact intervals decide the arc, widest first: each
// kUnknown span, and each kCrossing span that reaches the arc and is not certainly inside
// the union of the spans kept before it (the union of the kept pairs' exact intervals on
// the open arc is then that of all pairs, points between intervals included).
std::vector<uint32_t> spans_that_matter(const ArcSpans& arc, const std::vector<ArcSpans::Span>& spans);

// The directions strictly inside an open arc shorter than 180 degrees, in order along it,
// each as the indices of the directions equal to it. Their angles along the arc decide
// what they can; the exact order only what lies within 1e-8 rad of an end of the arc or of
// another direction. The probe's strip events of neighbouring triangles coincide often,
// and sorting all of them exactly evaluated every tie (a tenth of occt_TR12J_OCC F234).
std::vector<std::vector<uint32_t>> in_order_along(const sphere::Arc& open_arc,
                                                  const std::vector<exact::ExactVec>& directions);

}  // namespace gvm
