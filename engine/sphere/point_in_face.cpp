#include "sphere/point_in_face.h"

#include <array>
#include <vector>

namespace gvm::sphere {
namespace {

using exact::ExactVec;

// The sign of a polynomial in two infinitesimals, delta << epsilon << 1, given by its
// terms in decreasing order of magnitude: the first non-zero term decides.
Sign lexicographic(std::initializer_list<Sign> terms) {
  for (Sign s : terms) {
    if (s != Sign::kZero) return s;
  }
  return Sign::kZero;
}

struct Piece {
  ExactVec a, b;  // a minor arc a -> b
};

std::vector<Piece> boundary_pieces(const Face& f) {
  std::vector<Piece> pieces;
  for (const Loop& loop : f.loops) {
    for (const Arc& arc : loop.arcs) {
      std::vector<ExactVec> v = split_arc(arc);
      for (size_t i = 0; i + 1 < v.size(); ++i) pieces.push_back({v[i], v[i + 1]});
    }
  }
  return pieces;
}

}  // namespace

// Not on the boundary, u is inside iff a path from u to a point known to be inside crosses
// the boundary an even number of times. The known point is m + epsilon N: m inside a
// boundary piece, N its circle normal (the region is on its left). The path starts at
// u + delta R for a fixed direction R; u is off the boundary, so its side is that of the
// perturbed point, and the perturbations make every crossing test non-degenerate.
bool point_in_face(const Face& f, const ExactVec& u) {
  for (const Loop& loop : f.loops) {
    for (const Arc& arc : loop.arcs) {
      if (arc_contains(arc, u)) return true;
    }
  }
  const std::vector<Piece> pieces = boundary_pieces(f);
  const ExactVec r = ExactVec::from_point({0.6180339887498949, 0.7071067811865476, 1.0});
  for (const Piece& ref : pieces) {
    const ExactVec m = ref.a + ref.b;  // strictly inside the minor arc
    if (exact::parallel(u, m)) continue;  // u = -m: take another reference
    const ExactVec n = cross(ref.a, ref.b);
    int crossings = 0;
    bool degenerate = false;
    for (const Piece& p : pieces) {
      const ExactVec q = cross(p.a, p.b);
      // Sides of the path's endpoints with respect to the piece's circle.
      Sign su = lexicographic({exact::sign_dot(u, q), exact::sign_dot(r, q)});
      Sign sm = lexicographic({exact::sign_dot(m, q), exact::sign_dot(n, q)});
      // Sides of the piece's endpoints with respect to the path's circle (u+dR) x (m+eN).
      auto side = [&](const ExactVec& x) {
        return lexicographic({exact::sign_det(u, m, x), exact::sign_det(u, n, x),
                              exact::sign_det(r, m, x), exact::sign_det(r, n, x)});
      };
      Sign sa = side(p.a), sb = side(p.b);
      if (su == Sign::kZero || sm == Sign::kZero || sa == Sign::kZero || sb == Sign::kZero) {
        degenerate = true;
        break;
      }
      // Minor arcs cross iff each separates the other's endpoints and the two circles
      // meet at the same one of their two intersection points.
      if (su != sm && sa != sb && su == -sa) ++crossings;
    }
    if (!degenerate) return crossings % 2 == 0;
  }
  return false;  // unreachable for a face with a boundary
}

}  // namespace gvm::sphere
