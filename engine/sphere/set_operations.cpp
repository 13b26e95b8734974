#include "sphere/set_operations.h"

#include <vector>

#include "sphere/arrangement.h"
#include "sphere/image_overlay.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;

constexpr int kA = 0, kB = 1;  // layers of the two operands

// Both operands in one labelled arrangement, with the membership rules of the header for
// its cells.
class PairOverlay {
 public:
  PairOverlay(const SphericalImage& a, const SphericalImage& b) : arr_(build(a, b)) {}

  const Arrangement& arrangement() const { return arr_; }

  bool face_in(uint32_t f, int k) const { return arr_.coverage(f, k) > 0; }
  bool edge_in(uint32_t e, int k) const {
    return arr_.edge_on_layer(e, k) || face_in(left(e), k) || face_in(right(e), k);
  }
  bool vertex_in(uint32_t v, int k) const {
    if (arr_.vertex_has_point(v, k)) return true;
    const auto& out = arr_.vertices()[v].out;
    if (out.empty()) return face_in(0, k);  // the only vertex, in the only face
    for (uint32_t h : out) {
      const Arrangement::HalfEdge& he = arr_.half_edges()[h];
      if (arr_.edge_on_layer(he.edge, k) || face_in(he.face, k)) return true;
    }
    return false;
  }
  // In the interior of the set: every face around the cell is in it.
  bool edge_interior(uint32_t e, int k) const { return face_in(left(e), k) && face_in(right(e), k); }
  bool vertex_interior(uint32_t v, int k) const {
    const auto& out = arr_.vertices()[v].out;
    if (out.empty()) return face_in(0, k);
    for (uint32_t h : out) {
      if (!face_in(arr_.half_edges()[h].face, k)) return false;
    }
    return true;
  }

 private:
  static Arrangement build(const SphericalImage& a, const SphericalImage& b) {
    std::vector<ArrangementArc> arcs;
    std::vector<ArrangementPoint> points;
    add_image(a, kA, arcs, points);
    add_image(b, kB, arcs, points);
    const ExactVec r = generic_direction(arcs, points);
    const int coverage[2] = {face_winding(a, r), face_winding(b, r)};
    return Arrangement(arcs, points, 2, r, coverage);
  }
  uint32_t left(uint32_t e) const { return arr_.half_edges()[2 * e].face; }
  uint32_t right(uint32_t e) const { return arr_.half_edges()[2 * e + 1].face; }

  Arrangement arr_;
};

// Vertices of a loop, every arc split into pieces shorter than 180 degrees.
std::vector<ExactVec> loop_vertices(const Loop& loop) {
  std::vector<ExactVec> out;
  for (const Arc& arc : loop.arcs) {
    std::vector<ExactVec> v = split_arc(arc);
    out.insert(out.end(), v.begin(), v.end() - 1);
  }
  return out;
}

// A face of one loop all of whose vertices lie in the closed hemisphere of every one of
// its arcs is the intersection of those hemispheres: the loop then lies on the boundary
// of that convex region, and a simple loop on a convex boundary is all of it, with the
// region on the same (left) side. Checked exactly; large faces are left general, which
// is always correct (only slower to test).
bool is_convex(const Face& f) {
  constexpr size_t kMaxChecks = 1 << 14;
  if (f.loops.size() != 1) return false;
  const std::vector<Arc>& arcs = f.loops[0].arcs;
  const std::vector<ExactVec> vertices = loop_vertices(f.loops[0]);
  if (arcs.size() * vertices.size() > kMaxChecks) return false;
  for (const Arc& arc : arcs) {
    for (const ExactVec& v : vertices) {
      if (exact::sign_dot(v, arc.normal) == Sign::kNegative) return false;
    }
  }
  return true;
}

SphericalImage with_convex_faces_marked(const SphericalImage& image) {
  if (image.is_full_sphere() || image.faces().empty()) return image;
  SphericalImage out;
  for (Face f : image.faces()) {
    f.convex = is_convex(f);
    out.add_face(std::move(f));
  }
  for (const Arc& a : image.curves()) out.add_curve(a);
  for (const ExactVec& p : image.points()) out.add_point(p);
  return out;
}

}  // namespace

SphericalImage set_union(const SphericalImage& a, const SphericalImage& b) {
  const PairOverlay o(a, b);
  return with_convex_faces_marked(o.arrangement().extract(
      [&](uint32_t f) { return o.face_in(f, kA) || o.face_in(f, kB); },
      [&](uint32_t e) { return o.edge_in(e, kA) || o.edge_in(e, kB); },
      [&](uint32_t v) { return o.vertex_in(v, kA) || o.vertex_in(v, kB); }));
}

SphericalImage set_intersection(const SphericalImage& a, const SphericalImage& b) {
  const PairOverlay o(a, b);
  return with_convex_faces_marked(o.arrangement().extract(
      [&](uint32_t f) { return o.face_in(f, kA) && o.face_in(f, kB); },
      [&](uint32_t e) { return o.edge_in(e, kA) && o.edge_in(e, kB); },
      [&](uint32_t v) { return o.vertex_in(v, kA) && o.vertex_in(v, kB); }));
}

SphericalImage set_difference(const SphericalImage& a, const SphericalImage& b) {
  const PairOverlay o(a, b);
  return with_convex_faces_marked(o.arrangement().extract(
      [&](uint32_t f) { return o.face_in(f, kA) && !o.face_in(f, kB); },
      [&](uint32_t e) { return o.edge_in(e, kA) && !o.edge_interior(e, kB); },
      [&](uint32_t v) { return o.vertex_in(v, kA) && !o.vertex_interior(v, kB); }));
}

bool is_subset(const SphericalImage& a, const SphericalImage& b) {
  if (a.is_empty() || b.is_full_sphere()) return true;
  const PairOverlay o(a, b);
  const Arrangement& arr = o.arrangement();
  for (uint32_t f = 0; f < arr.faces().size(); ++f) {
    if (o.face_in(f, kA) && !o.face_in(f, kB)) return false;
  }
  for (uint32_t e = 0; e < arr.edges().size(); ++e) {
    if (o.edge_in(e, kA) && !o.edge_in(e, kB)) return false;
  }
  for (uint32_t v = 0; v < arr.vertices().size(); ++v) {
    if (o.vertex_in(v, kA) && !o.vertex_in(v, kB)) return false;
  }
  return true;
}

}  // namespace gvm::sphere
