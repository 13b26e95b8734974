// Random closed sets of directions built exactly, for the brute-force tests of the set
// operations, the coverage overlay and the clearance: local visibility maps of a few
// small-integer normals (convex polygons, lunes, hemispheres, great circles, half circles,
// arcs, points, antipodal pairs, empty, full), unions of those as overlapping cells, arcs
// of every length, points, hemispheres. Small integers on purpose: exact ties (a vertex
// of one set on a circle of another, shared circles, antipodes) are frequent.
#pragma once

#include <array>
#include <random>
#include <vector>

#include "exact/exact_vec.h"
#include "sphere/local_visibility_map.h"
#include "sphere/spherical_image.h"

namespace gvm::sphere::testing {

using exact::ExactVec;
using I3 = std::array<int, 3>;

inline ExactVec iv(int x, int y, int z) { return ExactVec::from_point({double(x), double(y), double(z)}); }
inline ExactVec iv(const I3& a) { return iv(a[0], a[1], a[2]); }

inline int uniform(std::mt19937_64& rng, int lo, int hi) {
  return std::uniform_int_distribution<int>(lo, hi)(rng);
}

// A non-zero integer vector with coordinates in [-r, r].
inline I3 random_int_vec(std::mt19937_64& rng, int r) {
  for (;;) {
    I3 a = {uniform(rng, -r, r), uniform(rng, -r, r), uniform(rng, -r, r)};
    if (a[0] != 0 || a[1] != 0 || a[2] != 0) return a;
  }
}

inline ExactVec random_direction(std::mt19937_64& rng, int r) { return iv(random_int_vec(rng, r)); }

// All the cells of the parts in one image (overlapping 2-cells stay separate faces).
inline SphericalImage combine(const std::vector<SphericalImage>& parts) {
  SphericalImage out;
  for (const SphericalImage& p : parts) {
    if (p.is_full_sphere()) return SphericalImage::full_sphere();
    for (const Face& f : p.faces()) out.add_face(f);
    for (const Arc& a : p.curves()) out.add_curve(a);
    for (const ExactVec& q : p.points()) out.add_point(q);
  }
  return out;
}

// LVM of 1 to 5 normals spread around a common direction: mostly convex polygons and
// lunes, with every degenerate outcome now and then. Half of the time the normals come
// from the 26 directions with coordinates in {-1, 0, 1}, so that different sets share
// circles and vertices (arcs along one another's boundaries, faces sharing edges).
inline SphericalImage random_lvm(std::mt19937_64& rng) {
  if (uniform(rng, 0, 1) == 0) {
    std::vector<ExactVec> normals;
    const int k = uniform(rng, 1, 4);
    for (int i = 0; i < k; ++i) normals.push_back(random_direction(rng, 1));
    return local_visibility_map(normals);
  }
  const I3 base = random_int_vec(rng, 4);
  const int k = uniform(rng, 1, 5);
  const int spread = uniform(rng, 1, 4);
  std::vector<ExactVec> normals;
  for (int i = 0; i < k; ++i) {
    I3 d = random_int_vec(rng, spread);
    normals.push_back(iv(2 * base[0] + d[0], 2 * base[1] + d[1], 2 * base[2] + d[2]));
  }
  if (uniform(rng, 0, 9) == 0) {
    normals.push_back(-normals[0]);  // a great circle, a half circle or antipodal points
  }
  return local_visibility_map(normals);
}

// One arc: minor, exactly 180 degrees (antipodal ends), longer than 180, or a full circle.
inline Arc random_arc(std::mt19937_64& rng) {
  const int r = uniform(rng, 1, 3);  // r = 1: on the circles of the {-1, 0, 1} normals often
  for (;;) {
    const ExactVec p = random_direction(rng, r), q = random_direction(rng, r);
    const ExactVec n = exact::cross(p, q);
    if (exact::is_zero(n)) continue;
    switch (uniform(rng, 0, 5)) {
      case 0:
        return {p, -p, n};          // 180 degrees, on the circle through q
      case 1:
        return {p, q, -n};          // the long way round
      case 2:
        return {{}, {}, n, true};   // a whole great circle
      default:
        return {p, q, n};           // minor
    }
  }
}

inline SphericalImage random_curves(std::mt19937_64& rng) {
  SphericalImage out;
  const int k = uniform(rng, 1, 2);
  for (int i = 0; i < k; ++i) out.add_curve(random_arc(rng));
  return out;
}

inline SphericalImage random_points(std::mt19937_64& rng) {
  SphericalImage out;
  const int k = uniform(rng, 1, 3);
  for (int i = 0; i < k; ++i) {
    const ExactVec p = random_direction(rng, 3);
    out.add_point(p);
    if (uniform(rng, 0, 2) == 0) out.add_point(-p);  // antipodal pair
  }
  return out;
}

// Any of the kinds above, and mixtures.
inline SphericalImage random_image(std::mt19937_64& rng) {
  switch (uniform(rng, 0, 12)) {
    case 0:
      return random_curves(rng);
    case 1:
      return random_points(rng);
    case 2:
      return SphericalImage::hemisphere(random_direction(rng, 2));
    case 3:
      return uniform(rng, 0, 1) ? SphericalImage::full_sphere() : SphericalImage::empty();
    case 4:
    case 5:
      return combine({random_lvm(rng), random_lvm(rng)});
    case 6:
      return combine({random_lvm(rng), random_lvm(rng), random_lvm(rng)});
    case 7:
      return combine({random_lvm(rng), random_curves(rng), random_points(rng)});
    default:
      return random_lvm(rng);
  }
}

// Every vertex of the image (loop vertices, arc ends, split points of long arcs, points),
// its antipode, and a direction strictly inside every arc piece: where boundaries meet.
inline void add_special_directions(const SphericalImage& img, std::vector<ExactVec>& out) {
  auto add_arc = [&](const Arc& a) {
    std::vector<ExactVec> v = split_arc(a);
    for (size_t i = 0; i < v.size(); ++i) {
      out.push_back(v[i]);
      out.push_back(-v[i]);
      if (i + 1 < v.size()) out.push_back(v[i] + v[i + 1]);
    }
  };
  for (const Face& f : img.faces()) {
    for (const Loop& l : f.loops) {
      for (const Arc& a : l.arcs) add_arc(a);
    }
  }
  for (const Arc& a : img.curves()) add_arc(a);
  for (const ExactVec& p : img.points()) {
    out.push_back(p);
    out.push_back(-p);
  }
}

// Random small-integer directions plus the special directions of every image.
inline std::vector<ExactVec> probe_directions(std::mt19937_64& rng,
                                              const std::vector<const SphericalImage*>& images,
                                              int random_count = 200) {
  std::vector<ExactVec> out;
  for (int i = 0; i < random_count; ++i) out.push_back(random_direction(rng, 5));
  for (const SphericalImage* img : images) add_special_directions(*img, out);
  return out;
}

// u lies on the boundary loop of some 2-cell of the image.
inline bool on_face_boundary(const SphericalImage& img, const ExactVec& u) {
  for (const Face& f : img.faces()) {
    for (const Loop& l : f.loops) {
      for (const Arc& a : l.arcs) {
        if (arc_contains(a, u)) return true;
      }
    }
  }
  return false;
}

// u lies in some 2-cell (a point of Int(B) when off every face boundary).
inline bool in_some_face(const SphericalImage& img, const ExactVec& u) {
  if (img.is_full_sphere()) return true;
  for (const Face& f : img.faces()) {
    if (face_contains(f, u)) return true;
  }
  return false;
}

}  // namespace gvm::sphere::testing
