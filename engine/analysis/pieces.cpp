// Pieces of a set of faces: the planar ones (--split), and the ones with a common
// direction (automatic features that no one direction sees whole).
#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <numeric>

#include "analysis/analysis_impl.h"
#include "parallel/interrupt.h"

namespace gvm {

using namespace analysis_internal;

namespace {

constexpr uint32_t kNone = UINT32_MAX;

// Each triangle of `tris` to the smallest triangle of its maximal edge-connected planar
// piece (one plane, one orientation); kNone outside `tris`.
std::vector<uint32_t> planar_roots(const SolidMesh& mesh, const std::vector<uint32_t>& tris) {
  std::vector<uint32_t> piece(mesh.triangles.size(), kNone);
  for (uint32_t t : tris) piece[t] = t;
  auto find = [&](uint32_t x) {
    while (piece[x] != x) x = piece[x] = piece[piece[x]];
    return x;
  };
  for (uint32_t t : tris) {
    for (uint32_t n : mesh.neighbor[t]) {
      if (piece[n] == kNone || !coplanar_alike(mesh, t, n)) continue;
      const uint32_t a = find(t), b = find(n);
      if (a != b) piece[std::max(a, b)] = std::min(a, b);
    }
  }
  for (uint32_t t : tris) piece[t] = find(t);
  return piece;
}

double area(const SolidMesh& mesh, uint32_t t) {
  const Triangle& tri = mesh.triangles[t];
  const Point3 &a = mesh.points[tri[0]], &b = mesh.points[tri[1]], &c = mesh.points[tri[2]];
  const double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, v[3] = {c.x - a.x, c.y - a.y, c.z - a.z};
  const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
}

std::vector<std::vector<uint32_t>> sorted(std::vector<std::vector<uint32_t>> pieces) {
  for (auto& p : pieces) std::sort(p.begin(), p.end());
  std::sort(pieces.begin(), pieces.end());
  return pieces;
}

// Grows pieces of input faces (units) whose normals, and those of the faces of N_S beside
// them, keep a common direction: each piece's LVM(S + N_S) is then not empty (N_S of a
// piece lies in the union of its units' N_S, whose hemispheres all hold the direction);
// whether the rest of the part leaves it one is for the piece's GVM to say.
class VisibleGrowth {
 public:
  VisibleGrowth(const Part& part, const std::vector<uint32_t>& tris, bool along_normal)
      : part_(part), mesh_(part.mesh()), along_normal_(along_normal), unit_of_(mesh_.triangles.size(), kNone) {
    const SolidMesh& mesh = mesh_;
    for (uint32_t t : tris) {
      const uint32_t face = mesh.triangle_face[t];
      auto [it, added] = unit_index_.emplace(face, static_cast<uint32_t>(units_.size()));
      if (added) units_.push_back({face, {}});
      units_[it->second].triangles.push_back(t);
      unit_of_[t] = it->second;
    }
  }

  // Each piece grows from its seed while some direction is left or, along_normal, while
  // the seed's normal d sees every face and its N_S (the flat top takes the fillets'
  // upper halves, not the walls below): pieces a machinist would cut from one side. A
  // seed that d does not serve grows while some direction is left.
  std::vector<std::vector<uint32_t>> pieces(const std::vector<uint32_t>& tris) {
    std::vector<uint32_t> piece_of(units_.size(), kNone), tried(units_.size(), kNone);
    std::vector<std::vector<uint32_t>> out;
    for (uint32_t seed : seed_order(tris)) {
      if (piece_of[seed] != kNone) continue;
      const uint32_t id = static_cast<uint32_t>(out.size());
      out.emplace_back();
      const exact::ExactVec d = normal_of(mesh_, units_[seed].triangles.front());
      const bool along_d = along_normal_ && serves(d, seed);
      DirectionSet lvm = DirectionSet::full_sphere();
      std::deque<uint32_t> queue{seed};
      while (!queue.empty()) {
        const uint32_t u = queue.front();
        queue.pop_front();
        if (piece_of[u] != kNone || tried[u] == id) continue;
        tried[u] = id;
        const bool admitted = along_d ? serves(d, u) : admit(lvm, u);
        if (!admitted && u != seed) continue;  // a seed with no direction of its own stays alone
        piece_of[u] = id;
        out[id].push_back(units_[u].face);
        if (!along_d && lvm.is_empty()) break;
        for (uint32_t t : units_[u].triangles) {
          for (uint32_t n : mesh_.neighbor[t]) {
            if (unit_of_[n] != kNone && piece_of[unit_of_[n]] == kNone) queue.push_back(unit_of_[n]);
          }
        }
      }
      interruption_point();
    }
    return sorted(std::move(out));
  }

 private:
  struct Unit {
    uint32_t face;
    std::vector<uint32_t> triangles;
  };

  // Units whose planar piece is largest first (the flat top before its fillets), then by
  // face; the areas only order the seeds.
  std::vector<uint32_t> seed_order(const std::vector<uint32_t>& tris) const {
    const std::vector<uint32_t> root = planar_roots(mesh_, tris);
    std::vector<double> piece_area(mesh_.triangles.size(), 0);
    for (uint32_t t : tris) piece_area[root[t]] += area(mesh_, t);
    std::vector<double> unit_area(units_.size(), 0);
    for (uint32_t u = 0; u < units_.size(); ++u) unit_area[u] = piece_area[root[units_[u].triangles.front()]];
    std::vector<uint32_t> order(units_.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
      return unit_area[a] != unit_area[b] ? unit_area[a] > unit_area[b] : units_[a].face < units_[b].face;
    });
    return order;
  }

  // The unit's triangles and its N_S: the faces whose hemispheres bound a piece's LVM.
  std::vector<uint32_t> constraining(uint32_t u) const {
    std::vector<uint32_t> tris = units_[u].triangles;
    const std::vector<uint32_t> beside = part_.neighbor_occluders(units_[u].triangles);
    tris.insert(tris.end(), beside.begin(), beside.end());
    return tris;
  }

  // Whether d lies in the closed hemisphere of every one of them (exact).
  bool serves(const exact::ExactVec& d, uint32_t u) const {
    for (uint32_t t : constraining(u)) {
      if (exact::sign_dot(normal_of(mesh_, t), d) == Sign::kNegative) return false;
    }
    return true;
  }

  // lvm intersected with the hemispheres of the normals of the unit and of its N_S, when
  // that leaves a direction (exact); lvm is left as it was otherwise.
  bool admit(DirectionSet& lvm, uint32_t u) const {
    DirectionSet next = lvm;
    const std::vector<uint32_t> tris = constraining(u);
    for (size_t i = 0; i < tris.size(); ++i) {
      if (i > 0 && coplanar_alike(mesh_, tris.front(), tris[i])) continue;
      const Direction n(std::make_shared<const exact::ExactVec>(normal_of(mesh_, tris[i])));
      if (next.within_closed_hemisphere(n)) continue;
      next = next.intersection(DirectionSet::hemisphere(n));
      if (next.is_empty()) return false;
    }
    lvm = std::move(next);
    return true;
  }

  const Part& part_;
  const SolidMesh& mesh_;
  bool along_normal_;
  std::vector<uint32_t> unit_of_;
  std::map<uint32_t, uint32_t> unit_index_;
  std::vector<Unit> units_;
};

}  // namespace

std::vector<std::vector<uint32_t>> Analysis::planar_pieces(std::span<const uint32_t> faces) const {
  const SolidMesh& mesh = impl_->part.mesh();
  auto tris = triangles_of(mesh, faces);
  if (!tris.ok()) return {};
  const std::vector<uint32_t> root = planar_roots(mesh, *tris);
  std::vector<std::vector<uint32_t>> by_root(mesh.triangles.size());
  for (uint32_t t : *tris) by_root[root[t]].push_back(t);
  std::vector<std::vector<uint32_t>> out;
  for (const auto& members : by_root) {
    if (!members.empty()) out.push_back(input_faces(mesh, members));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::vector<uint32_t>> Analysis::visible_pieces(std::span<const uint32_t> faces, Growth growth) const {
  const SolidMesh& mesh = impl_->part.mesh();
  auto tris = triangles_of(mesh, faces);
  if (!tris.ok()) return {};
  try {
    return VisibleGrowth(impl_->part, *tris, growth == Growth::kAlongSeedNormal).pieces(*tris);
  } catch (const Interrupted&) {
    return {};
  }
}

}  // namespace gvm
