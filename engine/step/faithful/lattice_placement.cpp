// The lattice placement of lattice_placement.h.
#include "step/faithful/lattice_placement.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "sphere/union_find.h"

namespace gvm::faithful {
namespace {

using LD = long double;
using LVec = std::array<LD, 3>;

constexpr int kNoFrame = -1;
constexpr uint32_t kNoAnchor = UINT32_MAX;

LD ldot(const IVec& a, const LVec& t) { return LD(a.x) * t[0] + LD(a.y) * t[1] + LD(a.z) * t[2]; }

// The nearest integer of a long double beyond int64 (the long double's 64 bits, exactly).
i128 round_to_i128(LD v) {
  const LD whole = std::round(v);
  const bool negative = whole < 0;
  LD a = negative ? -whole : whole;
  const LD high = std::floor(std::ldexp(a, -64));
  const i128 out = (i128(uint64_t(high)) << 64) + i128(uint64_t(a - std::ldexp(high, 64)));
  return negative ? -out : out;
}

// 0, 1 or 2 for a coordinate axis (canonical vectors are positive), else -1.
int coordinate_axis(const IVec& c) {
  for (int k = 0; k < 3; ++k)
    if (c[k] == 1 && c[(k + 1) % 3] == 0 && c[(k + 2) % 3] == 0) return k;
  return -1;
}

int slot_of(const Frame& f, const IVec& v) {
  for (int k = 0; k < 3; ++k)
    if (f.axis[k] == v) return k;
  return -1;
}

struct PointConstraints {
  std::vector<uint32_t> planes, rulings;
};

class Solver {
 public:
  explicit Solver(const PlacementProblem& p)
      : p_(p), dirs_(*p.directions), n_(uint32_t(p.target.size())),
        uf_(3 * size_t(n_) + p.planes.size() + 3 * p.rulings.size()) {}

  Placement run() {
    to_grid_units();
    collect();
    choose_ruling_frames();
    choose_point_frames();
    choose_anchors();
    unite();
    values();
    Placement out;
    out.grid.resize(n_);
    for (uint32_t i = 0; i < n_; ++i) out.grid[i] = position(i);
    for (uint32_t r : anchored_order_) place_along_anchor(r, out.grid);  // parents first
    report(out);
    return out;
  }

 private:
  const IVec& vec(uint32_t cls) const { return dirs_.classes[cls].exact; }
  uint32_t point_var(uint32_t p, int k) const { return 3 * p + uint32_t(k); }
  uint32_t plane_var(uint32_t f) const { return 3 * n_ + f; }
  uint32_t ruling_var(uint32_t r, int k) const { return 3 * n_ + uint32_t(p_.planes.size()) + 3 * r + uint32_t(k); }

  void to_grid_units() {
    target_.resize(n_);
    for (uint32_t i = 0; i < n_; ++i)
      for (int k = 0; k < 3; ++k) target_[i][k] = std::ldexp(LD(p_.target[i][k]), -p_.grid_exponent);
  }

  void collect() {
    at_.resize(n_);
    for (uint32_t f = 0; f < p_.planes.size(); ++f)
      for (uint32_t q : p_.planes[f].points) at_[q].planes.push_back(f);
    for (uint32_t r = 0; r < p_.rulings.size(); ++r)
      for (uint32_t q : p_.rulings[r].points) at_[q].rulings.push_back(r);
  }

  int score(const Frame& f, const PointConstraints& c) const {
    int s = 0;
    for (uint32_t pl : c.planes) s += slot_of(f, vec(p_.planes[pl].cls)) >= 0;
    for (uint32_t r : c.rulings) s += slot_of(f, vec(p_.rulings[r].cls)) >= 0;
    return s;
  }

  // Each ruling in the frame of its axis that fits most of its points' other faces.
  void choose_ruling_frames() {
    ruling_frame_.assign(p_.rulings.size(), kNoFrame);
    for (uint32_t r = 0; r < p_.rulings.size(); ++r) {
      int best = -1;
      for (int f = 0; f < int(dirs_.frames.size()); ++f) {
        if (slot_of(dirs_.frames[f], vec(p_.rulings[r].cls)) < 0) continue;
        int s = 0;
        for (uint32_t q : p_.rulings[r].points) s += score(dirs_.frames[f], at_[q]);
        if (s > best) best = s, ruling_frame_[r] = f;
      }
    }
  }

  // A point on rulings takes the frame of most of them; else the frame of most of its planes.
  void choose_point_frames() {
    frame_.assign(n_, kNoFrame);
    for (uint32_t q = 0; q < n_; ++q) {
      const PointConstraints& c = at_[q];
      int best = -1;
      for (int f = 0; f < int(dirs_.frames.size()); ++f) {
        int s = score(dirs_.frames[f], c);
        if (s == 0) continue;
        if (!c.rulings.empty()) {
          const int own = int(std::count_if(c.rulings.begin(), c.rulings.end(),
                                            [&](uint32_t r) { return ruling_frame_[r] == f; }));
          if (own == 0) continue;
          s += 4 * own;
        }
        if (s > best) best = s, frame_[q] = f;
      }
    }
  }

  // A ruling of one frame that meets a ruling of another at a point (an oblique hole
  // breaking into a bore along z) cannot have both on lattice lines of their frames. So
  // rulings are anchored: such a point is placed in one ruling's frame, and the other
  // ruling's line is drawn through it along its axis, its other points moved onto that line
  // (their planes normal to it kept as closely as the grid allows). The rulings that meet
  // form a graph whose edges are the points where they meet; each component is walked from
  // one root on its lattice, and every ruling reached is anchored at the point it was
  // reached by, so that every ruling of a tree of meetings holds exactly. A ruling reached
  // twice (a cycle of meetings) keeps its first anchor; the second point is a miss.
  void choose_anchors() {
    anchor_.assign(p_.rulings.size(), kNoAnchor);
    meets_.assign(p_.rulings.size(), {});
    for (uint32_t q = 0; q < n_; ++q) {
      const std::vector<uint32_t>& rs = at_[q].rulings;
      for (size_t i = 0; i < rs.size(); ++i)
        for (size_t j = i + 1; j < rs.size(); ++j) {
          const bool cross = ruling_frame_[rs[i]] != ruling_frame_[rs[j]];
          meets_[rs[i]].push_back({rs[j], q, cross});
          meets_[rs[j]].push_back({rs[i], q, cross});
        }
    }
    reached_.assign(p_.rulings.size(), false);
    std::vector<bool> seen(p_.rulings.size(), false);
    std::vector<uint32_t> roots(p_.rulings.size());
    std::iota(roots.begin(), roots.end(), 0u);
    // Roots on the lowest frame first (the coordinate frame's lattice is the finest).
    std::stable_sort(roots.begin(), roots.end(), [&](uint32_t a, uint32_t b) { return ruling_frame_[a] < ruling_frame_[b]; });
    for (uint32_t root : roots) {
      if (seen[root] || std::none_of(meets_[root].begin(), meets_[root].end(), [](const Meet& m) { return m.cross; }))
        continue;
      std::vector<uint32_t> component = {root};  // joined by meetings across frames
      seen[root] = true;
      for (size_t k = 0; k < component.size(); ++k)
        for (const Meet& m : meets_[component[k]])
          if (m.cross && !seen[m.other]) seen[m.other] = true, component.push_back(m.other);
      if (cross_exactly(component)) {
        for (uint32_t r : component) reached_[r] = true;
        walk(crossings_.back().oblique_rulings);
      } else if (!reached_[root]) {
        reached_[root] = true;
        walk({root});
      }
    }
  }

  // Anchors every ruling reached from `queue`, at the point it was reached by: across frames
  // from any ruling, within a frame only from an anchored one (two rulings on one frame's
  // lattice meet exactly already).
  void walk(std::vector<uint32_t> queue) {
    for (size_t k = 0; k < queue.size(); ++k) {
      const uint32_t r = queue[k];
      for (const Meet& m : meets_[r]) {
        if (reached_[m.other] || (!m.cross && anchor_[r] == kNoAnchor)) continue;
        reached_[m.other] = true;
        if (!crossing_point_.count(m.point)) frame_[m.point] = ruling_frame_[r];
        anchor_[m.other] = m.point;
        anchored_order_.push_back(m.other);
        queue.push_back(m.other);
      }
    }
  }

  // Rulings along a coordinate axis e_k meeting rulings of one class c in a coordinate plane
  // (c . e_j = 0, e_j in c's frame: an oblique hole in the xz plane breaking into a bore
  // along z) can all meet exactly, however many times (a through cross hole meets each
  // ruling twice): in the plane x_j = S of a meeting, the e_k ruling is x_m = X and c's is
  // w . p = L (w its frame's third axis, w_j = 0), which meet at a grid point iff
  // L = w_m X (mod w_k). So the meeting rulings share S, every X of the component is put in
  // one residue class mod w_k (a move of at most |w_k| / 2 grid steps), and each L in the
  // class that follows; c's rulings are then lines through their meeting points. False
  // when the component is not of that form, or planes fix two X in different classes.
  bool cross_exactly(const std::vector<uint32_t>& component) {
    Crossing x;
    for (uint32_t r : component) {
      if (reached_[r]) return false;  // anchored already, from another component
      const int axis = ruling_frame_[r] == 0 ? coordinate_axis(vec(p_.rulings[r].cls)) : -1;
      if (axis >= 0) {
        if (x.k >= 0 && x.k != axis) return false;
        x.k = axis, x.axis_rulings.push_back(r);
      } else {
        if (!x.oblique_rulings.empty() && p_.rulings[x.oblique_rulings[0]].cls != p_.rulings[r].cls) return false;
        x.oblique_rulings.push_back(r);
      }
    }
    if (x.k < 0 || x.oblique_rulings.empty()) return false;
    const uint32_t first = x.oblique_rulings[0];
    const Frame& f = dirs_.frames[ruling_frame_[first]];
    const IVec& c = vec(p_.rulings[first].cls);
    for (int j = 0; j < 3 && x.j < 0; ++j) {
      if (j == x.k || c[j] != 0) continue;
      const IVec e = j == 0 ? IVec{1, 0, 0} : (j == 1 ? IVec{0, 1, 0} : IVec{0, 0, 1});
      if (slot_of(f, e) < 0) continue;
      x.j = j, x.m = 3 - j - x.k;
      for (const IVec& a : f.axis)
        if (a != c && a != e) x.w = a;
    }
    if (x.j < 0 || x.w[x.k] == 0) return false;
    for (uint32_t r : x.oblique_rulings)
      for (const Meet& m : meets_[r])
        if (m.cross && std::find(x.axis_rulings.begin(), x.axis_rulings.end(), m.other) == x.axis_rulings.end())
          return false;
    for (uint32_t r : x.oblique_rulings)
      for (const Meet& m : meets_[r]) {
        if (!m.cross) continue;
        frame_[m.point] = 0;
        crossing_point_[m.point] = {uint32_t(crossings_.size()), r};
        if (anchor_[r] == kNoAnchor) anchor_[r] = m.point, anchored_order_.push_back(r);
      }
    crossings_.push_back(std::move(x));
    return true;
  }

  // The meeting rulings of a crossing share their coordinate along e_j.
  void unite_crossings() {
    for (const Crossing& x : crossings_)
      for (uint32_t r : x.oblique_rulings) {
        uint32_t previous = UINT32_MAX;
        for (const Meet& m : meets_[r]) {
          if (!m.cross) continue;
          if (previous != UINT32_MAX) uf_.unite(ruling_var(previous, x.j), ruling_var(m.other, x.j));
          previous = m.other;
        }
      }
  }

  // After the values: every X of a crossing in one residue class, each L in the class that
  // follows.
  void settle_crossings() {
    for (Crossing& x : crossings_) {
      const int64_t mod = std::llabs(x.w[x.k]);
      std::optional<int64_t> fixed;
      for (uint32_t r : x.axis_rulings) {
        const uint32_t root = uf_.find(ruling_var(r, x.m));
        if (!plane_roots_.count(root)) continue;
        const int64_t residue = int64_t(((value_.at(root) % mod) + mod) % mod);
        if (fixed && *fixed != residue) x.settled = false;
        fixed = residue;
      }
      if (!x.settled) continue;
      x.residue = fixed ? *fixed : int64_t(((value_.at(uf_.find(ruling_var(x.axis_rulings[0], x.m))) % mod) + mod) % mod);
      for (uint32_t r : x.axis_rulings) {
        i128& v = value_.at(uf_.find(ruling_var(r, x.m)));
        v = nearest_in_class(v, x.residue, mod);
      }
      for (uint32_t r : x.oblique_rulings) {
        LD sum = 0;
        for (uint32_t q : p_.rulings[r].points) sum += ldot(x.w, target_[q]);
        const i128 want = round_to_i128(sum / LD(p_.rulings[r].points.size()));  // about 2^70
        line_[r] = nearest_in_class(want, i128(x.w[x.m]) * x.residue % mod, mod);
      }
    }
  }

  static i128 nearest_in_class(i128 v, i128 residue, int64_t mod) {
    residue = ((residue % mod) + mod) % mod;
    const i128 base = v - ((v % mod) + mod) % mod + residue;
    i128 best = base;
    for (i128 c : {base - mod, base + mod})
      if ((c > v ? c - v : v - c) < (best > v ? best - v : v - best)) best = c;
    return best;
  }

  // A meeting point of a settled crossing: x_m and x_j from the axis ruling, x_k where the
  // oblique ruling's line crosses.
  std::optional<IVec> crossing_position(uint32_t q) {
    auto it = crossing_point_.find(q);
    if (it == crossing_point_.end() || !crossings_[it->second.first].settled) return std::nullopt;
    const Crossing& x = crossings_[it->second.first];
    int64_t c[3];
    c[x.m] = int64_t(value_.at(uf_.find(point_var(q, x.m))));
    c[x.j] = int64_t(value_.at(uf_.find(point_var(q, x.j))));
    c[x.k] = int64_t((line_.at(it->second.second) - i128(x.w[x.m]) * c[x.m]) / x.w[x.k]);
    return IVec{c[0], c[1], c[2]};
  }

  void place_along_anchor(uint32_t r, std::vector<IVec>& grid) {
    const IVec& c = vec(p_.rulings[r].cls);
    const IVec a = grid[anchor_[r]];
    const LD cc = LD(dot(c, c));
    for (uint32_t q : p_.rulings[r].points) {
      if (q == anchor_[r] || crossing_position(q)) continue;  // on its line already
      LD t = ldot(c, {target_[q][0] - a.x, target_[q][1] - a.y, target_[q][2] - a.z}) / cc;
      for (uint32_t pl : at_[q].planes)
        if (vec(p_.planes[pl].cls) == c) t = (LD(value_.at(uf_.find(plane_var(pl))) * dot(c, c)) - LD(dot(c, a))) / cc;
      grid[q] = a + std::llround(t) * c;
    }
  }

  void unite() {
    unite_crossings();
    for (uint32_t f = 0; f < p_.planes.size(); ++f)
      for (uint32_t q : p_.planes[f].points) {
        const int k = frame_[q] == kNoFrame ? -1 : slot_of(dirs_.frames[frame_[q]], vec(p_.planes[f].cls));
        if (k >= 0) uf_.unite(point_var(q, k), plane_var(f));
      }
    for (uint32_t r = 0; r < p_.rulings.size(); ++r) {
      if (anchor_[r] != kNoAnchor) continue;
      const Frame& fr = dirs_.frames[ruling_frame_[r]];
      for (uint32_t q : p_.rulings[r].points) {
        if (frame_[q] != ruling_frame_[r]) continue;
        for (int k = 0; k < 3; ++k)
          if (fr.axis[k] != vec(p_.rulings[r].cls)) uf_.unite(point_var(q, k), ruling_var(r, k));
      }
    }
  }

  // Each variable's value: a plane's offset from the B-rep, else the mean coordinate of its
  // points (a ruling's include every point it should hold).
  void values() {
    struct Acc {
      std::optional<i128> plane;
      LD sum = 0;
      uint32_t count = 0;
      bool constrained = false;
    };
    std::map<uint32_t, Acc> acc;
    for (uint32_t f = 0; f < p_.planes.size(); ++f) {
      Acc& a = acc[uf_.find(plane_var(f))];
      a.constrained = true;
      if (a.plane) continue;
      const IVec& n = vec(p_.planes[f].cls);
      LVec point;
      for (int k = 0; k < 3; ++k) point[k] = std::ldexp(LD(p_.planes[f].point[k]), -p_.grid_exponent);
      a.plane = i128(std::llround(ldot(n, point) / LD(dot(n, n))));
    }
    for (uint32_t r = 0; r < p_.rulings.size(); ++r) {
      const Frame& fr = dirs_.frames[ruling_frame_[r]];
      for (int k = 0; k < 3; ++k) {
        if (fr.axis[k] == vec(p_.rulings[r].cls)) continue;
        Acc& a = acc[uf_.find(ruling_var(r, k))];
        a.constrained = true;
        for (uint32_t q : p_.rulings[r].points) {
          a.sum += ldot(fr.axis[k], target_[q]) / LD(dot(fr.axis[k], fr.axis[k]));
          ++a.count;
        }
      }
    }
    for (uint32_t q = 0; q < n_; ++q) {
      if (frame_[q] == kNoFrame) continue;
      const Frame& fr = dirs_.frames[frame_[q]];
      for (int k = 0; k < 3; ++k) {
        auto it = acc.find(uf_.find(point_var(q, k)));
        if (it == acc.end()) continue;
        it->second.sum += ldot(fr.axis[k], target_[q]) / LD(dot(fr.axis[k], fr.axis[k]));
        ++it->second.count;
      }
    }
    for (auto& [root, a] : acc) {
      value_[root] = a.plane ? *a.plane : i128(std::llround(a.count ? a.sum / a.count : 0));
      if (a.plane) plane_roots_.insert(root);
    }
    settle_crossings();
  }

  std::optional<i128> fixed(uint32_t q, int k) {
    auto it = value_.find(uf_.find(point_var(q, k)));
    if (it == value_.end()) return std::nullopt;
    return it->second;
  }

  IVec rounded(const LVec& t) const { return {std::llround(t[0]), std::llround(t[1]), std::llround(t[2])}; }

  // The lattice point of a-perp nearest to r (Babai over a reduced basis, four neighbours).
  IVec nearest_orthogonal(const IVec& a, const LVec& r) {
    auto it = basis_.find({a.x, a.y, a.z});
    if (it == basis_.end()) it = basis_.emplace(std::array<int64_t, 3>{a.x, a.y, a.z}, orthogonal_lattice(a)).first;
    const auto& [b1, b2] = it->second;
    const LD g11 = LD(dot(b1, b1)), g12 = LD(dot(b1, b2)), g22 = LD(dot(b2, b2));
    const LD r1 = ldot(b1, r), r2 = ldot(b2, r), det = g11 * g22 - g12 * g12;
    const LD alpha = (r1 * g22 - r2 * g12) / det, beta = (r2 * g11 - r1 * g12) / det;
    IVec best;
    LD best_d = -1;
    for (LD ia : {std::floor(alpha), std::ceil(alpha)})
      for (LD ib : {std::floor(beta), std::ceil(beta)}) {
        const IVec v = int64_t(ia) * b1 + int64_t(ib) * b2;
        const LD dx = v.x - r[0], dy = v.y - r[1], dz = v.z - r[2];
        const LD d = dx * dx + dy * dy + dz * dz;
        if (best_d < 0 || d < best_d) best_d = d, best = v;
      }
    return best;
  }

  IVec position(uint32_t q) {
    if (auto p = crossing_position(q)) return *p;
    const LVec& t = target_[q];
    if (frame_[q] == kNoFrame) return rounded(t);
    const Frame& fr = dirs_.frames[frame_[q]];
    std::optional<i128> x[3] = {fixed(q, 0), fixed(q, 1), fixed(q, 2)};
    IVec base;
    int free_slots = 0, free_k = -1, fixed_k = -1;
    for (int k = 0; k < 3; ++k) {
      if (x[k]) base = base + int64_t(*x[k]) * fr.axis[k], fixed_k = k;
      else ++free_slots, free_k = k;
    }
    const LVec rest = {t[0] - base.x, t[1] - base.y, t[2] - base.z};
    if (free_slots == 0) return base;
    if (free_slots == 3) return rounded(t);
    if (free_slots == 1) {
      const IVec& a = fr.axis[free_k];
      return base + std::llround(ldot(a, rest) / LD(dot(a, a))) * a;
    }
    return base + nearest_orthogonal(fr.axis[fixed_k], rest);
  }

  void report(Placement& out) {
    const LD unit = std::ldexp(LD(1), p_.grid_exponent);
    for (uint32_t q = 0; q < n_; ++q) {
      const IVec& g = out.grid[q];
      const LD dx = g.x * unit - p_.target[q][0], dy = g.y * unit - p_.target[q][1], dz = g.z * unit - p_.target[q][2];
      out.max_displacement_mm = std::max(out.max_displacement_mm, double(std::sqrt(dx * dx + dy * dy + dz * dz)));
    }
    for (uint32_t f = 0; f < p_.planes.size(); ++f) {
      const IVec& n = vec(p_.planes[f].cls);
      const i128 level = value_.at(uf_.find(plane_var(f))) * dot(n, n);
      Miss m{p_.planes[f].face, false, 0, 0};
      for (uint32_t q : p_.planes[f].points) {
        const i128 off = dot(n, out.grid[q]) - level;
        if (off == 0) continue;
        ++m.points;
        m.distance_mm = std::max(m.distance_mm, double(std::fabs(LD(off)) / std::sqrt(LD(dot(n, n))) * unit));
      }
      if (m.points) out.misses.push_back(m);
    }
    for (uint32_t r = 0; r < p_.rulings.size(); ++r) {
      const IVec& c = vec(p_.rulings[r].cls);
      const Frame& fr = dirs_.frames[ruling_frame_[r]];
      IVec anchor;  // a point of the ruling's line
      if (anchor_[r] != kNoAnchor) anchor = out.grid[anchor_[r]];
      else
        for (int k = 0; k < 3; ++k)
          if (fr.axis[k] != c) anchor = anchor + int64_t(value_.at(uf_.find(ruling_var(r, k)))) * fr.axis[k];
      Miss m{p_.rulings[r].face, true, 0, 0};
      for (uint32_t q : p_.rulings[r].points) {
        const IVec d = out.grid[q] - anchor;  // d x c exactly: up to 2^53 times 2^41
        const i128 x = i128(d.y) * c.z - i128(d.z) * c.y, y = i128(d.z) * c.x - i128(d.x) * c.z,
                   z = i128(d.x) * c.y - i128(d.y) * c.x;
        if (x == 0 && y == 0 && z == 0) continue;
        ++m.points;
        const LD len = std::sqrt(LD(x) * LD(x) + LD(y) * LD(y) + LD(z) * LD(z));
        m.distance_mm = std::max(m.distance_mm, double(len / std::sqrt(LD(dot(c, c))) * unit));
      }
      if (m.points) out.misses.push_back(m);
    }
  }

  const PlacementProblem& p_;
  const ExactDirections& dirs_;
  uint32_t n_;
  sphere::UnionFind uf_;
  std::vector<LVec> target_;
  std::vector<PointConstraints> at_;
  std::vector<int> ruling_frame_, frame_;
  std::vector<uint32_t> anchor_;  // per ruling: the point it is anchored at, or kNoAnchor
  std::vector<uint32_t> anchored_order_;
  struct Meet {
    uint32_t other, point;
    bool cross;  // the other ruling is of another frame
  };
  std::vector<std::vector<Meet>> meets_;  // per ruling
  std::vector<bool> reached_;
  struct Crossing {
    std::vector<uint32_t> axis_rulings, oblique_rulings;
    int k = -1, j = -1, m = -1;  // the axis, the shared coordinate, the third
    IVec w;                      // the oblique frame's axis in the plane of e_k and e_m
    int64_t residue = 0;
    bool settled = true;
  };
  std::vector<Crossing> crossings_;
  std::map<uint32_t, std::pair<uint32_t, uint32_t>> crossing_point_;  // point -> (crossing, oblique ruling)
  std::map<uint32_t, i128> line_;                                     // oblique ruling -> w . p on it
  std::set<uint32_t> plane_roots_;
  std::map<uint32_t, i128> value_;
  std::map<std::array<int64_t, 3>, std::array<IVec, 2>> basis_;
};

}  // namespace

Placement place_on_lattices(const PlacementProblem& problem) { return Solver(problem).run(); }

}  // namespace gvm::faithful
