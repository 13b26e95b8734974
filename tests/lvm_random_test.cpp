// Randomized brute force for the LVM: small-integer normal sets (duplicates, antipodes and
// exact ties on purpose) against independent exact integer arithmetic.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "io/sphere_proto.h"
#include "exact/exact_vec.h"
#include "gvm/v1/gvm.pb.h"
#include "sphere/local_visibility_map.h"
#include "sphere/spherical_image.h"

namespace {

using gvm::exact::ExactVec;
using gvm::sphere::local_visibility_map;
using gvm::sphere::SphericalImage;

using I3 = std::array<long long, 3>;
using i128 = __int128;

constexpr double kPi = 3.14159265358979323846;

ExactVec ev(const I3& v) {
  return ExactVec::from_point(
      {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])});
}
i128 dot(const I3& a, const I3& b) {
  return i128(a[0]) * b[0] + i128(a[1]) * b[1] + i128(a[2]) * b[2];
}
I3 cross(const I3& a, const I3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
i128 det(const I3& a, const I3& b, const I3& c) { return dot(a, cross(b, c)); }
bool zero(const I3& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }

bool in_lvm(const std::vector<I3>& normals, const I3& u) {
  for (const I3& n : normals) {
    if (dot(u, n) < 0) return false;
  }
  return true;
}

// n in the closed cone spanned by the normals (Caratheodory: by some linearly independent
// subset of at most three of them), decided with exact integer Cramer rules.
bool in_cone(const std::vector<I3>& g, const I3& n) {
  if (zero(n)) return true;
  size_t k = g.size();
  for (size_t i = 0; i < k; ++i) {
    if (zero(g[i])) continue;
    if (zero(cross(g[i], n)) && dot(g[i], n) > 0) return true;
    for (size_t j = i + 1; j < k; ++j) {
      I3 ab = cross(g[i], g[j]);
      if (zero(ab)) continue;
      if (det(g[i], g[j], n) == 0) {
        // n = l a + m b with l = (n x b).(a x b) / |a x b|^2, m = (a x n).(a x b) / |a x b|^2.
        if (dot(cross(n, g[j]), ab) >= 0 && dot(cross(g[i], n), ab) >= 0) return true;
      }
      for (size_t l = j + 1; l < k; ++l) {
        i128 d = det(g[i], g[j], g[l]);
        if (d == 0) continue;
        i128 d0 = det(n, g[j], g[l]), d1 = det(g[i], n, g[l]), d2 = det(g[i], g[j], n);
        auto nonneg = [d](i128 x) { return d > 0 ? x >= 0 : x <= 0; };
        if (nonneg(d0) && nonneg(d1) && nonneg(d2)) return true;
      }
    }
  }
  return false;
}

struct D3 {
  double x, y, z;
};
double dotd(const D3& a, const D3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 crossd(const D3& a, const D3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
D3 of(const gvm::v1::Vec3& v) { return {v.x(), v.y(), v.z()}; }

TEST(LvmRandom, ContainsAndHullAgainstIntegerBruteForce) {
  const unsigned seed = 20261122;
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(-2, 2), count(1, 8), pick(0, 9), scale(1, 3);
  std::normal_distribution<double> gauss;
  int dims[4] = {0, 0, 0, 0};
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<I3> normals;
    int k = count(rng);
    while (static_cast<int>(normals.size()) < k) {
      int r = pick(rng);
      if (!normals.empty() && r == 0) {  // duplicated direction
        I3 n = normals[rng() % normals.size()];
        long long s = scale(rng);
        normals.push_back({n[0] * s, n[1] * s, n[2] * s});
      } else if (!normals.empty() && r == 1) {  // antipodal direction
        I3 n = normals[rng() % normals.size()];
        normals.push_back({-n[0], -n[1], -n[2]});
      } else if (r == 2) {  // in the coordinate planes: more degenerate outcomes
        I3 n = {coord(rng), coord(rng), 0};
        if (!zero(n)) normals.push_back(n);
      } else {
        I3 n = {coord(rng), coord(rng), coord(rng)};
        if (!zero(n)) normals.push_back(n);
      }
    }
    std::vector<ExactVec> exact;
    for (const I3& n : normals) exact.push_back(ev(n));
    SphericalImage s = local_visibility_map(exact);
    auto trace = [&] {
      std::string t = "seed " + std::to_string(seed) + " trial " + std::to_string(trial) +
                      " normals";
      for (const I3& n : normals) {
        t += " (" + std::to_string(n[0]) + "," + std::to_string(n[1]) + "," +
             std::to_string(n[2]) + ")";
      }
      return t + " -> " + s.description();
    };
    dims[s.dimension() + 1]++;

    bool any_in = false;
    for (int p = 0; p < 40; ++p) {
      I3 u = {coord(rng), coord(rng), coord(rng)};
      if (zero(u)) continue;
      bool expected = in_lvm(normals, u);
      any_in = any_in || expected;
      ASSERT_EQ(s.contains(ev(u)), expected)
          << trace() << " probe (" << u[0] << "," << u[1] << "," << u[2] << ")";
      I3 n = {coord(rng), coord(rng), coord(rng)};
      if (zero(n)) continue;
      ASSERT_EQ(s.within_closed_hemisphere(ev(n)), in_cone(normals, n))
          << trace() << " hemisphere (" << n[0] << "," << n[1] << "," << n[2] << ")";
      ASSERT_EQ(gvm::sphere::in_spherical_convex_hull(exact, ev(n)), in_cone(normals, n))
          << trace();
    }
    if (any_in) ASSERT_GE(s.dimension(), 0) << trace();
    // Every vertex is in the set (closed), and the set is stable under equality.
    for (const auto& f : s.faces()) {
      for (const auto& l : f.loops) {
        for (const auto& a : l.arcs) {
          if (!a.full) ASSERT_TRUE(s.contains(a.start)) << trace();
        }
      }
    }
    for (const auto& a : s.curves()) {
      if (!a.full) ASSERT_TRUE(s.contains(a.start) && s.contains(a.end)) << trace();
    }
    for (const auto& p : s.points()) ASSERT_TRUE(s.contains(p)) << trace();
    std::vector<ExactVec> reversed(exact.rbegin(), exact.rend());
    ASSERT_TRUE(s == local_visibility_map(reversed)) << trace();

    if (trial % 10 != 0) continue;
    // Monte-Carlo area in doubles (independent of the engine), and the proto loops: every
    // arc shorter than 180 degrees, region on the left (sampled point-in-polygon test for
    // these convex loops).
    gvm::v1::SphericalImage proto;
    gvm::io::to_proto(s, &proto);
    ASSERT_EQ(proto.dimension(), s.dimension()) << trace();
    const int samples = 20000;
    int hits = 0;
    for (int i = 0; i < samples; ++i) {
      D3 u = {gauss(rng), gauss(rng), gauss(rng)};
      double len = std::sqrt(dotd(u, u));
      u = {u.x / len, u.y / len, u.z / len};
      double worst = 1;
      for (const I3& n : normals) {
        D3 nd = {double(n[0]), double(n[1]), double(n[2])};
        worst = std::min(worst, dotd(u, nd) / std::sqrt(dotd(nd, nd)));
      }
      hits += worst >= 0;
      if (std::fabs(worst) < 1e-6) continue;
      bool in_polygons = false;
      for (const auto& poly : proto.polygons()) {
        bool left_of_all = true;
        for (const auto& loop : poly.loops()) {
          int m = loop.vertices_size();
          for (int j = 0; j < m; ++j) {
            D3 a = of(loop.vertices(j)), b = of(loop.vertices((j + 1) % m));
            ASSERT_GT(dotd(a, b), -1 + 1e-12) << trace();
            if (dotd(crossd(a, b), u) < 0) left_of_all = false;
          }
        }
        in_polygons = in_polygons || left_of_all;
      }
      ASSERT_EQ(in_polygons, worst > 0) << trace();
    }
    double mc = 4 * kPi * hits / samples;
    ASSERT_NEAR(s.area(), mc, 0.2) << trace();
    ASSERT_NEAR(proto.area(), s.area(), 1e-12) << trace();
  }
  // The generator reaches every dimension.
  for (int d = 0; d < 4; ++d) EXPECT_GT(dims[d], 0) << "dimension " << d - 1;
}

}  // namespace
