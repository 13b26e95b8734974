#include "sphere/point_in_face.h"

#include <array>
#include <vector>

namespace gvm::sphere {
namespace {

using exact::ExactVec;

// The sign of a polynomial in two infinitesimals, delta << epsilon << 1, given by its
// terms in decreasing order of magnitude: the first non-zero term decides. The terms are
// evaluated only as far as needed (most are exact predicates that decide at the first).
template <class... Terms>
Sign lexicographic(const Terms&... terms) {
  Sign s = Sign::kZero;
  ((s == Sign::kZero ? (s = terms(), 0) : 0), ...);
  return s;
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
  std::vector<ExactVec> normals;  // circle normal of each piece, built once
  for (const Piece& p : pieces) normals.push_back(cross(p.a, p.b));
  const ExactVec r = ExactVec::from_point({0.6180339887498949, 0.7071067811865476, 1.0});
  for (size_t k = 0; k < pieces.size(); ++k) {
    const Piece& ref = pieces[k];
    const ExactVec m = ref.a + ref.b;  // strictly inside the minor arc
    if (exact::parallel(u, m)) continue;  // u = -m: take another reference
    const ExactVec& n = normals[k];
    int crossings = 0;
    bool degenerate = false;
    for (size_t i = 0; i < pieces.size(); ++i) {
      const Piece& p = pieces[i];
      const ExactVec& q = normals[i];
      // Sides of the path's endpoints with respect to the piece's circle. On the
      // reference piece itself m . n = 0 by construction and n . n > 0.
      Sign su = lexicographic([&] { return exact::sign_dot(u, q); }, [&] { return exact::sign_dot(r, q); });
      Sign sm = i == k ? Sign::kPositive
                       : lexicographic([&] { return exact::sign_dot(m, q); }, [&] { return exact::sign_dot(n, q); });
      // Sides of the piece's endpoints with respect to the path's circle (u+dR) x (m+eN).
      auto side = [&](const ExactVec& x) {
        return lexicographic([&] { return exact::sign_det(u, m, x); }, [&] { return exact::sign_det(u, n, x); },
                             [&] { return exact::sign_det(r, m, x); }, [&] { return exact::sign_det(r, n, x); });
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
