#include "mesh/tri_intersect.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "exact/predicates.h"
#include "parallel/interrupt.h"

namespace gvm::mesh_internal {
namespace {

using exact::orient2d;
using exact::orient3d;

constexpr Sign kZ = Sign::kZero;

int drop_axis(const Point3& a, const Point3& b, const Point3& c) {
  for (int ax = 2; ax >= 0; --ax)
    if (orient2d(a, b, c, ax) != kZ) return ax;
  return 2;
}


// x in the closed triangle pqr (non-degenerate in projection `drop`).
bool point_in_tri_2d(const Point3& x, const Point3& p, const Point3& q, const Point3& r,
                     int drop) {
  Sign s = orient2d(p, q, r, drop);
  return orient2d(p, q, x, drop) != -s && orient2d(q, r, x, drop) != -s &&
         orient2d(r, p, x, drop) != -s;
}

bool mixed(Sign a, Sign b, Sign c) {
  bool pos = a == Sign::kPositive || b == Sign::kPositive || c == Sign::kPositive;
  bool neg = a == Sign::kNegative || b == Sign::kNegative || c == Sign::kNegative;
  return pos && neg;
}

}  // namespace

// Closed 2D segments in projection `drop` have a common point.
bool seg_seg_2d(const Point3& a, const Point3& b, const Point3& c, const Point3& d, int drop) {
  Sign o1 = orient2d(a, b, c, drop), o2 = orient2d(a, b, d, drop);
  Sign o3 = orient2d(c, d, a, drop), o4 = orient2d(c, d, b, drop);
  if (o1 == kZ && o2 == kZ) {
    // collinear in the projection (the segments lie on one line of the plane)
    int i = (drop + 1) % 3, j = (drop + 2) % 3;
    for (int ax : {i, j}) {
      double lo1 = std::min(a[ax], b[ax]), hi1 = std::max(a[ax], b[ax]);
      double lo2 = std::min(c[ax], d[ax]), hi2 = std::max(c[ax], d[ax]);
      if (hi1 < lo2 || hi2 < lo1) return false;
    }
    return true;
  }
  return o1 * o2 != Sign::kPositive && o3 * o4 != Sign::kPositive;
}

bool segment_meets_triangle(const Point3& a, const Point3& b, const Point3& p, const Point3& q,
                            const Point3& r) {
  Sign oa = orient3d(p, q, r, a), ob = orient3d(p, q, r, b);
  if (oa * ob == Sign::kPositive) return false;
  if (oa == kZ && ob == kZ) {
    int drop = drop_axis(p, q, r);
    return point_in_tri_2d(a, p, q, r, drop) || point_in_tri_2d(b, p, q, r, drop) ||
           seg_seg_2d(a, b, p, q, drop) || seg_seg_2d(a, b, q, r, drop) ||
           seg_seg_2d(a, b, r, p, drop);
  }
  // The line ab crosses the plane once, inside the closed segment.
  return !mixed(orient3d(a, b, p, q), orient3d(a, b, q, r), orient3d(a, b, r, p));
}

bool triangles_meet(const Point3 t[3], const Point3 u[3]) {
  Sign d0 = orient3d(u[0], u[1], u[2], t[0]), d1 = orient3d(u[0], u[1], u[2], t[1]),
       d2 = orient3d(u[0], u[1], u[2], t[2]);
  if (d0 == d1 && d1 == d2 && d0 != kZ) return false;
  if (d0 == kZ && d1 == kZ && d2 == kZ) {
    int drop = drop_axis(t[0], t[1], t[2]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (seg_seg_2d(t[i], t[(i + 1) % 3], u[j], u[(j + 1) % 3], drop)) return true;
    return point_in_tri_2d(t[0], u[0], u[1], u[2], drop) ||
           point_in_tri_2d(u[0], t[0], t[1], t[2], drop);
  }
  Sign e0 = orient3d(t[0], t[1], t[2], u[0]), e1 = orient3d(t[0], t[1], t[2], u[1]),
       e2 = orient3d(t[0], t[1], t[2], u[2]);
  if (e0 == e1 && e1 == e2 && e0 != kZ) return false;
  // Not coplanar: the intersection, if any, is a segment whose ends lie on edges.
  for (int i = 0; i < 3; ++i) {
    if (segment_meets_triangle(t[i], t[(i + 1) % 3], u[0], u[1], u[2])) return true;
    if (segment_meets_triangle(u[i], u[(i + 1) % 3], t[0], t[1], t[2])) return true;
  }
  return false;
}

bool improper_contact(const std::vector<Point3>& P, const Triangle& t, const Triangle& u) {
  int shared = 0, ti[3], ui[3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t[i] == u[j]) {
        ti[shared] = i;
        ui[shared] = j;
        ++shared;
      }
  if (shared == 3) return true;
  if (shared == 2) {
    // Shared edge (x, y): improper only if coplanar with both third vertices on one side.
    const Point3 &x = P[t[ti[0]]], &y = P[t[ti[1]]];
    const Point3& a = P[t[3 - ti[0] - ti[1]]];
    const Point3& b = P[u[3 - ui[0] - ui[1]]];
    if (orient3d(x, y, a, b) != kZ) return false;
    int drop = drop_axis(x, y, a);
    return orient2d(x, y, a, drop) == orient2d(x, y, b, drop);
  }
  if (shared == 1) {
    // Shared vertex s: they meet elsewhere iff an edge opposite s meets the other triangle.
    const Point3 &a1 = P[t[(ti[0] + 1) % 3]], &a2 = P[t[(ti[0] + 2) % 3]];
    const Point3 &b1 = P[u[(ui[0] + 1) % 3]], &b2 = P[u[(ui[0] + 2) % 3]];
    return segment_meets_triangle(a1, a2, P[u[0]], P[u[1]], P[u[2]]) ||
           segment_meets_triangle(b1, b2, P[t[0]], P[t[1]], P[t[2]]);
  }
  const Point3 tp[3] = {P[t[0]], P[t[1]], P[t[2]]};
  const Point3 up[3] = {P[u[0]], P[u[1]], P[u[2]]};
  return triangles_meet(tp, up);
}

std::optional<std::pair<uint32_t, uint32_t>> find_self_intersection(
    const std::vector<Point3>& P, const std::vector<Triangle>& tris,
    const std::vector<uint32_t>& tri_face) {
  const size_t nt = tris.size();
  if (nt < 2) return std::nullopt;
  struct Box {
    double lo[3], hi[3];
  };
  std::vector<Box> box(nt);
  double glo[3] = {INFINITY, INFINITY, INFINITY}, ghi[3] = {-INFINITY, -INFINITY, -INFINITY};
  double mean_ext = 0;
  for (size_t t = 0; t < nt; ++t) {
    for (int ax = 0; ax < 3; ++ax) {
      double a = P[tris[t][0]][ax], b = P[tris[t][1]][ax], c = P[tris[t][2]][ax];
      box[t].lo[ax] = std::min({a, b, c});
      box[t].hi[ax] = std::max({a, b, c});
      glo[ax] = std::min(glo[ax], box[t].lo[ax]);
      ghi[ax] = std::max(ghi[ax], box[t].hi[ax]);
    }
    // Heuristic only (cell size): rounding here never affects a decision.
    mean_ext += std::max({box[t].hi[0] - box[t].lo[0], box[t].hi[1] - box[t].lo[1],
                          box[t].hi[2] - box[t].lo[2]});
  }
  mean_ext /= double(nt);
  // Coordinates near the double range (a span of 1e308 - -1e308) make the differences
  // overflow: the grid is then laid on the coordinates halved, which keeps every
  // difference finite (cell coordinates only need to be monotone in the coordinate).
  double span = std::max({ghi[0] - glo[0], ghi[1] - glo[1], ghi[2] - glo[2]});
  const double scale = std::isfinite(span) && std::isfinite(mean_ext) ? 1.0 : 0.5;
  if (scale != 1) {
    span = std::max({ghi[0] * scale - glo[0] * scale, ghi[1] * scale - glo[1] * scale,
                     ghi[2] * scale - glo[2] * scale});
    mean_ext = 0;  // each term divided first: the sum stays finite
    for (const Box& b : box) {
      mean_ext += std::max({b.hi[0] * scale - b.lo[0] * scale, b.hi[1] * scale - b.lo[1] * scale,
                            b.hi[2] * scale - b.lo[2] * scale}) / double(nt);
    }
  }
  double cell = std::max(mean_ext, span / 2048.0);
  if (!(cell > 0) || !std::isfinite(cell)) cell = 1;

  // Cell coordinates are a monotone function of the coordinate, so two boxes that overlap
  // share at least the cell of the lower corner of their intersection: each pair is tested
  // in exactly that cell.
  std::vector<std::pair<uint64_t, uint32_t>> entries;
  for (int attempt = 0;; ++attempt) {
    int64_t n[3];
    for (int ax = 0; ax < 3; ++ax) {
      // At most 2^20 cells an axis; compared as doubles, never cast beyond int64.
      const double extent = (ghi[ax] * scale - glo[ax] * scale) / cell;
      n[ax] = extent < double(1 << 20) ? std::max<int64_t>(int64_t(extent) + 1, 1) : int64_t(1) << 20;
    }
    auto idx = [&](double x, int ax) {
      double f = std::floor((x * scale - glo[ax] * scale) / cell);
      return std::clamp<int64_t>(f < 0 ? 0 : (f > double(n[ax] - 1) ? n[ax] - 1 : int64_t(f)),
                                 0, n[ax] - 1);
    };
    // The cells of every box, counted in parallel, then stored in parallel at offsets that
    // keep the order of the triangles.
    auto cells_of = [&](size_t t, int64_t l[3], int64_t h[3]) {
      for (int ax = 0; ax < 3; ++ax) l[ax] = idx(box[t].lo[ax], ax), h[ax] = idx(box[t].hi[ax], ax);
      return uint64_t(h[0] - l[0] + 1) * uint64_t(h[1] - l[1] + 1) * uint64_t(h[2] - l[2] + 1);
    };
    std::vector<uint64_t> offset(nt + 1, 0);
    tbb::parallel_for(size_t{0}, nt, [&](size_t t) {
      int64_t l[3], h[3];
      offset[t + 1] = cells_of(t, l, h);
    });
    // A budget of entries; a box over too many cells (one long sliver among small
    // triangles can cover millions) fails the attempt before anything is stored, and the
    // next attempt doubles the cell. The last attempt keeps every entry, whatever their
    // number: by then the cell is 2^21 times span / 2048 and a box covers at most 2 cells
    // an axis.
    const bool last = attempt > 20;
    const uint64_t budget = 32 * uint64_t(nt) + 1024;
    bool too_many = false;
    for (size_t t = 0; t < nt && !too_many; ++t) {
      too_many = !last && offset[t + 1] > budget - offset[t];
      offset[t + 1] += offset[t];
    }
    if (!too_many) {
      entries.resize(offset[nt]);
      tbb::parallel_for(size_t{0}, nt, [&](size_t t) {
        int64_t l[3], h[3];
        cells_of(t, l, h);
        size_t k = offset[t];
        for (int64_t x = l[0]; x <= h[0]; ++x)
          for (int64_t y = l[1]; y <= h[1]; ++y)
            for (int64_t z = l[2]; z <= h[2]; ++z)
              entries[k++] = {(uint64_t(x) << 42) | (uint64_t(y) << 21) | uint64_t(z), uint32_t(t)};
      });
      interruption_point();
      tbb::parallel_sort(entries.begin(), entries.end());
      interruption_point();  // a cancelled sort stops half done
      // The contact of entry a with a later entry of its cell, the first such in their
      // order; in parallel over the entries (big cells hold most of the pairs).
      auto contact_from = [&](size_t a) -> std::optional<std::pair<uint32_t, uint32_t>> {
        const uint64_t key = entries[a].first;
        const uint32_t ta = entries[a].second;
        const Box& A = box[ta];
        for (size_t b = a + 1; b < entries.size() && entries[b].first == key; ++b) {
          const uint32_t tb = entries[b].second;
          if (tri_face[ta] == tri_face[tb]) continue;
          const Box& B = box[tb];
          bool overlap = true;
          int64_t c[3];
          for (int ax = 0; ax < 3 && overlap; ++ax) {
            if (A.hi[ax] < B.lo[ax] || B.hi[ax] < A.lo[ax]) overlap = false;
            c[ax] = idx(std::max(A.lo[ax], B.lo[ax]), ax);
          }
          if (!overlap) continue;
          if (((uint64_t(c[0]) << 42) | (uint64_t(c[1]) << 21) | uint64_t(c[2])) != key) continue;
          if (improper_contact(P, tris[ta], tris[tb])) {
            uint32_t fa = tri_face[ta], fb = tri_face[tb];
            return std::make_pair(std::min(fa, fb), std::max(fa, fb));
          }
        }
        return std::nullopt;
      };
      // The first entry with a contact: the pair named in the message does not depend on
      // the number of threads.
      std::atomic<size_t> first{entries.size()};
      tbb::parallel_for(size_t{0}, entries.size(), [&](size_t a) {
        if (a >= first.load(std::memory_order_relaxed) || !contact_from(a)) return;
        for (size_t seen = first.load(); a < seen && !first.compare_exchange_weak(seen, a);) {
        }
      });
      interruption_point();  // entries left untested when cancelled
      if (first == entries.size()) return std::nullopt;
      return contact_from(first);
    }
    cell *= 2;
  }
}

}  // namespace gvm::mesh_internal
