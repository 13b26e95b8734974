#include "visibility/occlusion_culling.h"

#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "parallel/interrupt.h"
#include "sphere/box_tree.h"
#include "sphere/d3.h"
#include "visibility/face_estimate.h"
#include "visibility/face_tree.h"
#include "visibility/tier_seeds.h"

namespace gvm {
namespace {

using exact::ExactVec;
using namespace sphere;  // D3, Box

// A direction within kRadius of x: its estimate, else its exact value rounded.
D3 direction(const ExactVec& x) {
  const exact::UnitEstimate e = exact::unit_estimate(x);
  return e.radius <= kRadius ? e.unit : x.unit();
}

// A minor piece of a boundary arc of the union so far, in doubles, within kRadius of the
// exact one, and a box around it; `exact` is the minor arc (or point) of which it is a
// piece.
struct ArcEstimate {
  D3 a, b, normal;
  Box box;
  uint32_t exact = 0;
};

// An exact minor arc, or a point (from == to, no normal).
struct ExactPiece {
  ExactVec from, to, normal;
  bool point = false;
};

// The arc in pieces of at most a right angle (an arc of a half circle or more, as a
// window's side or a long side of a face can give, fits no small box and no test below).
void add_pieces(const ArrangementArc& arc, uint32_t exact, std::vector<ArcEstimate>& out) {
  const D3 a = direction(arc.from), b = direction(arc.to), n = normalized(arc.normal.unit());
  const D3 side = normalized(cross(n, a));
  double turn = std::atan2(dot(b, side), dot(b, a));
  if (turn < 0) turn += 2 * M_PI;
  // Whether the arc is minor is decided exactly: near a turn of 0 or 2 pi the doubles cannot.
  if (exact::sign_det(arc.from, arc.to, arc.normal) == Sign::kPositive) {
    if (turn > M_PI) turn = turn > 1.5 * M_PI ? 0 : M_PI;
  } else if (turn < M_PI) {
    turn = turn < 0.5 * M_PI ? 2 * M_PI : M_PI;
  }
  const int pieces = std::max(1, static_cast<int>(std::ceil(turn / (M_PI / 2))));
  D3 from = a;
  for (int k = 1; k <= pieces; ++k) {
    const double t = turn * k / pieces;
    const D3 to = k == pieces ? b : add(D3{a[0] * std::cos(t), a[1] * std::cos(t), a[2] * std::cos(t)}, side, std::sin(t));
    // The ends are within kRadius (and the rounding of the turn) of points of the arc.
    const exact::UnitEstimate ef{from, 4 * kRadius}, et{to, 4 * kRadius};
    out.push_back({from, to, n, arc_box(ef, et), exact});
    from = to;
  }
}

// The pieces of an arc of any length (a full circle too), and its minor arcs.
void add_pieces(const sphere::Arc& arc, std::vector<ArcEstimate>& out, std::vector<ExactPiece>& exact) {
  const std::vector<ExactVec> v = sphere::split_arc(arc);
  for (size_t k = 0; k + 1 < v.size(); ++k) {
    add_pieces(ArrangementArc{v[k], v[k + 1], arc.normal}, static_cast<uint32_t>(exact.size()), out);
    exact.push_back({v[k], v[k + 1], arc.normal});
  }
}

// The curves and points of an image, and its 2-cells' boundaries, as pieces.
void add_pieces(const sphere::SphericalImage& image, std::vector<ArcEstimate>& out, std::vector<ExactPiece>& exact) {
  for (const sphere::Face& f : image.faces()) {
    for (const sphere::Loop& loop : f.loops) {
      for (const sphere::Arc& arc : loop.arcs) add_pieces(arc, out, exact);
    }
  }
  for (const sphere::Arc& arc : image.curves()) add_pieces(arc, out, exact);
  // A point is an arc of no length: separated() then needs a side of the face it lies
  // strictly outside.
  for (const ExactVec& p : image.points()) {
    const D3 u = direction(p);
    const exact::UnitEstimate e{u, 4 * kRadius};
    out.push_back({u, u, D3{}, arc_box(e, e), static_cast<uint32_t>(exact.size())});
    exact.push_back({p, p, ExactVec{}, true});
  }
}

// A great circle separates the face from the arc: the arc's own circle (all the face's
// vertices strictly on one side of it), or the circle of a side of the face (both ends
// of the arc strictly outside it; the arc is minor, so all of it is).
bool separated(const FaceEstimate& f, const ArcEstimate& arc) {
  bool above = true, below = true;
  for (const D3& u : f.u) {
    const double d = dot(arc.normal, u);
    above = above && d > kSlack;
    below = below && d < -kSlack;
  }
  if (above || below) return true;
  for (size_t j = 0; j < f.inward.size(); ++j) {
    const double limit = -(kSlack + f.error[j]);
    if (dot(f.inward[j], arc.a) < limit && dot(f.inward[j], arc.b) < limit) return true;
  }
  return false;
}

// Whether the arc misses the open face: a great circle weakly separates them, the arc's own
// (every vertex of the face on one closed side: the open face lies in one open side) or a
// side's (both ends of the minor arc on its closed outer side). Where the doubles say an
// end or a vertex lies within the slack of the circle, the sign is decided exactly; on CAD
// parts faces often run along the union's boundary, sharing its circles exactly, and
// separated() cannot leave those out. `v` are the face's exact vertices.
bool interior_separated(const FaceEstimate& f, std::span<const ExactVec> v, const ArcEstimate& arc,
                        const ExactPiece& exact) {
  if (separated(f, arc)) return true;
  if (!exact.point) {
    bool above = true, below = true;  // every vertex above (below) the circle, up to the slack
    for (const D3& u : f.u) {
      const double d = dot(arc.normal, u);
      above = above && d > -kSlack;
      below = below && d < kSlack;
    }
    for (const int side : {1, -1}) {
      if (!(side > 0 ? above : below)) continue;
      bool weakly = true;
      for (size_t k = 0; k < f.u.size() && weakly; ++k) {
        const double d = side * dot(arc.normal, f.u[k]);
        weakly = d > kSlack || exact::sign_dot(exact.normal, v[k]) != (side > 0 ? Sign::kNegative : Sign::kPositive);
      }
      if (weakly) return true;
    }
  }
  for (size_t j = 0; j < f.inward.size(); ++j) {
    const double limit = kSlack + f.error[j];
    auto outside = [&](const D3& end, const ExactVec& x) {
      const double d = dot(f.inward[j], end);
      return d < -limit || (d < limit && exact::sign_det(v[j], v[(j + 1) % v.size()], x) != Sign::kPositive);
    };
    if (dot(f.inward[j], arc.a) < limit && dot(f.inward[j], arc.b) < limit && outside(arc.a, exact.from) &&
        outside(arc.b, exact.to)) {
      return true;
    }
  }
  return false;
}

// The union of the tiers so far, and what the test of a face against it needs.
class UnionSoFar {
 public:
  UnionSoFar(sphere::Region region, std::span<const FaceEstimate> est, std::span<const uint32_t> in_union,
             std::span<const ClipWindow> windows)
      : region_(std::move(region)), windows_(windows) {
    for (const ArrangementArc& a : region_.boundary) {
      add_pieces(a, static_cast<uint32_t>(exact_arcs_.size()), arcs_);
      exact_arcs_.push_back({a.from, a.to, a.normal});
    }
    arc_tree_.emplace(boxes_of(arcs_));
    face_tree_.emplace(est, in_union);
  }

  const sphere::Region& region() const { return region_; }

  // Whether face f (exact vertices v) certainly lies inside the union: no boundary arc
  // meets its open inside, and a point inside it lies strictly inside a face of the union
  // (and inside a window, when the union was clipped to windows). Its open inside then
  // lies in the union's interior, and the closed face in the union.
  bool holds(const FaceEstimate& f, std::span<const ExactVec> v) const {
    if (!f.certain || !interior_misses(f, v, arcs_, exact_arcs_, *arc_tree_)) return false;
    const D3 c = centre(f);
    return strictly_inside(f, c) && in_interior(c);
  }

  // V, the directions of `needed` left outside the union's interior (never the whole
  // sphere: the union has an interior), and rim, those of them on the boundary of
  // `needed`, for out_of_reach.
  void leave(const sphere::SphericalImage& needed, const sphere::SphericalImage& left,
             const sphere::SphericalImage& rim) {
    if (needed.faces().size() == 1 && needed.faces()[0].convex && needed.curves().empty() && needed.points().empty()) {
      for (const sphere::Loop& loop : needed.faces()[0].loops) {
        for (const sphere::Arc& arc : loop.arcs) needed_sides_.push_back(normalized(arc.normal.unit()));
      }
    }
    add_pieces(left, left_arcs_, left_exact_);
    left_tree_.emplace(boxes_of(left_arcs_));
    std::vector<ExactPiece> unused;
    add_pieces(rim, rim_arcs_, unused);
    rim_tree_.emplace(boxes_of(rim_arcs_));
  }

  // Whether face f (exact vertices v) certainly cannot change the union's interior on
  // `needed`: no boundary arc, curve or point of V meets its open inside, so that lies
  // wholly inside a 2-cell of V or wholly outside V, and a point inside f lies outside
  // `needed` or inside the union's interior, so outside V; and the closed face misses the
  // rim. A direction x of V keeps a neighbourhood that the union covers with f iff it
  // covers it without: the points f adds there lie in its open inside (the union is
  // closed, and f's sides are nowhere dense), so outside V, so inside the union's interior
  // or outside `needed`, and the last only near the rim, which f does not meet.
  bool out_of_reach(const FaceEstimate& f, std::span<const ExactVec> v) const {
    if (!f.certain || !left_tree_ || !interior_misses(f, v, left_arcs_, left_exact_, *left_tree_) ||
        !misses(f, rim_arcs_, *rim_tree_)) {
      return false;
    }
    const D3 c = centre(f);
    return strictly_inside(f, c) && (outside_needed(c) || in_interior(c));
  }

 private:
  static D3 centre(const FaceEstimate& f) {
    D3 sum{};
    for (const D3& u : f.u) sum = add(sum, u);
    return normalized(sum);
  }

  // Whether a unit vector certainly lies outside `needed`, when that is one convex face.
  bool outside_needed(const D3& c) const {
    return std::any_of(needed_sides_.begin(), needed_sides_.end(), [&](const D3& n) { return dot(n, c) < -kSlack; });
  }

  static std::vector<Box> boxes_of(const std::vector<ArcEstimate>& arcs) {
    std::vector<Box> boxes;
    for (const ArcEstimate& e : arcs) boxes.push_back(e.box);
    return boxes;
  }

  static bool misses(const FaceEstimate& f, const std::vector<ArcEstimate>& arcs, const BoxTree& tree) {
    return !tree.visit_overlapping(f.box, [&](uint32_t a) { return !separated(f, arcs[a]); });
  }

  static bool interior_misses(const FaceEstimate& f, std::span<const ExactVec> v, const std::vector<ArcEstimate>& arcs,
                              const std::vector<ExactPiece>& exact, const BoxTree& tree) {
    return !tree.visit_overlapping(f.box, [&](uint32_t a) {
      return !interior_separated(f, v, arcs[a], exact[arcs[a].exact]);
    });
  }

  // Whether a unit vector certainly lies strictly inside a face of the union (and inside a
  // window, when the union was clipped to windows).
  bool in_interior(const D3& c) const {
    if (!windows_.empty()) {
      const ExactVec x = ExactVec::from_point({c[0], c[1], c[2]});
      if (std::none_of(windows_.begin(), windows_.end(),
                       [&](const ClipWindow& w) { return w.contains_strictly(x); })) {
        return false;
      }
    }
    return face_tree_->holds(c);
  }

  sphere::Region region_;
  std::span<const ClipWindow> windows_;
  std::vector<ArcEstimate> arcs_;
  std::vector<ExactPiece> exact_arcs_;
  std::optional<BoxTree> arc_tree_;
  std::optional<FaceTree> face_tree_;  // of the faces in the union
  std::vector<D3> needed_sides_;  // inward normals of `needed`, when that is one convex face
  std::vector<ArcEstimate> left_arcs_;
  std::vector<ExactPiece> left_exact_;
  std::optional<BoxTree> left_tree_;
  std::vector<ArcEstimate> rim_arcs_;  // V on the boundary of `needed`
  std::optional<BoxTree> rim_tree_;
};

// The boundary of a closed set: its 2-cells' loops, its curves and its points.
sphere::SphericalImage boundary_of(const sphere::SphericalImage& set) {
  sphere::SphericalImage out;
  for (const sphere::Face& f : set.faces()) {
    for (const sphere::Loop& loop : f.loops) {
      for (const sphere::Arc& arc : loop.arcs) out.add_curve(arc);
    }
  }
  for (const sphere::Arc& arc : set.curves()) out.add_curve(arc);
  for (const ExactVec& p : set.points()) out.add_point(p);
  return out;
}

}  // namespace

sphere::Region union_by_tiers(std::span<const std::vector<ExactVec>> faces, std::span<const uint32_t> kept,
                              std::span<const ClipWindow> windows,
                              const std::function<sphere::Region(std::span<const uint32_t>)>& union_of,
                              const ExactVec& reference, TieredUnionStatistics* stats,
                              const TierPolicy& policy, const sphere::SphericalImage* needed) {
  // Faces by their positions in `kept`, largest first.
  std::vector<FaceEstimate> est(kept.size());
  tbb::parallel_for(size_t{0}, kept.size(), [&](size_t k) { est[k] = estimate_face(faces[kept[k]]); });
  interruption_point();
  std::vector<uint32_t> order(kept.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return est[a].area > est[b].area; });
  // The first tier: the largest faces, and beside them, in a large union, the faces that
  // cover what those leave of the occluded directions on `needed` (tier_seeds.h).
  const size_t largest = std::max(policy.min_first_tier, order.size() / policy.first_tier_share);
  size_t first_tier = largest;
  if (needed && order.size() >= policy.seed_from && order.size() <= policy.seed_until && largest < order.size()) {
    const std::span<const uint32_t> by_size(order);
    std::vector<uint8_t> seed(kept.size(), 0);
    for (uint32_t k : tier_seeds(est, by_size.first(largest), by_size.subspan(largest), *needed,
                                 policy.seed_samples_per_face * order.size())) {
      seed[k] = 1;
    }
    first_tier = std::stable_partition(order.begin() + largest, order.end(), [&](uint32_t k) { return seed[k] != 0; }) -
                 order.begin();
    spdlog::debug("union by tiers: {} faces join the {} largest in the first tier", first_tier - largest, largest);
  }
  TieredUnionStatistics local;
  local.faces = order.size();
  std::vector<uint32_t> in_union;  // positions
  std::optional<UnionSoFar> so_far;
  const sphere::SphericalImage rim = needed ? boundary_of(*needed) : sphere::SphericalImage{};
  // Each later tier twice the one before (after a seeded first tier, from the size of the
  // largest faces').
  auto next_tier = [&](size_t next, size_t tier) { return next == first_tier && first_tier > largest ? largest : 2 * tier; };
  for (size_t next = 0, tier = first_tier;; next += tier, tier = next_tier(next, tier)) {
    std::span<const uint32_t> candidates(order.data() + next, std::min(tier, order.size() - next));
    std::vector<uint8_t> inside(candidates.size(), 0);
    if (so_far) {
      tbb::parallel_for(size_t{0}, candidates.size(),
                        [&](size_t k) {
                          const FaceEstimate& f = est[candidates[k]];
                          const std::vector<ExactVec>& v = faces[kept[candidates[k]]];
                          inside[k] = so_far->holds(f, v) || so_far->out_of_reach(f, v);
                        });
      interruption_point();
    }
    std::vector<uint32_t> members;
    for (size_t k = 0; k < candidates.size(); ++k) {
      if (!inside[k]) members.push_back(candidates[k]);
    }
    const size_t left_out = candidates.size() - members.size();
    const bool large = candidates.size() >= policy.large_tier;
    if (local.tiers == 1 && large && left_out * policy.pays_from < candidates.size()) {
      spdlog::debug("union by tiers: {} of {} faces of tier 2 left out: one union of all faces", left_out,
                    candidates.size());
      if (stats) *stats = {.tiers = 1, .faces = order.size(), .one_union = true};
      return union_of(kept);
    }
    ++local.tiers;
    local.left_out += left_out;
    spdlog::debug("union by tiers: tier {}: {} faces, {} left out", local.tiers, candidates.size(), left_out);
    std::vector<uint32_t> member_faces;
    for (uint32_t k : members) member_faces.push_back(kept[k]);
    std::vector<sphere::Region> parts;
    if (so_far) parts.push_back(so_far->region());
    parts.push_back(union_of(member_faces));
    sphere::Region region = sphere::region_union(std::move(parts), reference);
    if (next + tier >= order.size()) {
      if (stats) *stats = local;
      return region;
    }
    in_union.insert(in_union.end(), members.begin(), members.end());
    if (needed) {
      sphere::SphericalImage left = sphere::outside_interior(*needed, region, reference);
      spdlog::debug("union by tiers: {:.4g} of the LVM's {:.4g} sr left outside the union of {} tiers", left.area(),
                    needed->area(), local.tiers);
      if (left.is_empty()) {
        local.not_needed = order.size() - (next + tier);
        spdlog::debug("union by tiers: the LVM lies inside the first {} tiers: {} faces not needed", local.tiers,
                      local.not_needed);
        if (stats) *stats = local;
        return region;
      }
      so_far.emplace(std::move(region), est, in_union, windows);
      if (!left.is_full_sphere()) {
        so_far->leave(*needed, left, sphere::outside_interior(rim, so_far->region(), reference));
      }
    } else {
      so_far.emplace(std::move(region), est, in_union, windows);
    }
  }
}

}  // namespace gvm
