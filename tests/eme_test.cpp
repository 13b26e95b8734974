// The effective Minkowski envelope on configurations whose projection is known.
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "exact/exact_vec.h"
#include "visibility/effective_minkowski_envelope.h"

namespace gvm {
namespace {

using exact::ExactVec;

ExactVec diff(const SolidMesh& m, uint32_t q, uint32_t p) {
  return ExactVec::from_point(m.points[q]) - ExactVec::from_point(m.points[p]);
}

// A "mesh" holding just the triangles the envelope reads.
SolidMesh two_triangles(const std::array<Point3, 6>& pts) {
  SolidMesh m;
  m.points.assign(pts.begin(), pts.end());
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  return m;
}

// Lemma 3: for two disjoint triangles in general position the envelope is one patch, and
// its border projects to the boundary of the convex spherical polygon Phi(F_O + (-F_S)):
// every one of the nine difference directions lies on the closed left of every border arc.
TEST(Eme, DisjointTrianglesGiveOneConvexPatch) {
  const unsigned seed = 11;
  SCOPED_TRACE("seed " + std::to_string(seed));
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> c(-20, 20);
  int tested = 0;
  for (int iter = 0; iter < 200; ++iter) {
    std::array<Point3, 6> pts;
    for (int i = 0; i < 3; ++i) pts[i] = {double(c(rng)), double(c(rng)), double(c(rng))};
    for (int i = 3; i < 6; ++i) pts[i] = {double(c(rng)), double(c(rng)), double(c(rng)) + 60};
    SolidMesh m = two_triangles(pts);
    if (exact::is_zero(exact::triangle_normal(pts[0], pts[1], pts[2])) ||
        exact::is_zero(exact::triangle_normal(pts[3], pts[4], pts[5]))) {
      continue;
    }
    std::vector<uint32_t> s = {0}, o = {1};
    EffectiveMinkowskiEnvelope eme = compute_effective_minkowski_envelope(m, s, o);
    ASSERT_EQ(eme.statistics.patches, 1u) << "iteration " << iter;
    ASSERT_GE(eme.border.size(), 3u);
    // A single cycle with multiplicity one.
    std::map<std::pair<uint32_t, uint32_t>, int> out_degree, in_degree;
    for (const auto& e : eme.border) {
      ASSERT_EQ(e.multiplicity, 1);
      ++out_degree[{e.q0, e.p0}];
      ++in_degree[{e.q1, e.p1}];
    }
    ASSERT_EQ(out_degree, in_degree);
    for (const auto& e : eme.border) {
      ExactVec x0 = diff(m, e.q0, e.p0), x1 = diff(m, e.q1, e.p1);
      ASSERT_FALSE(exact::parallel(x0, x1));
      for (uint32_t q = 3; q < 6; ++q) {
        for (uint32_t p = 0; p < 3; ++p) {
          ASSERT_NE(exact::sign_det(x0, x1, diff(m, q, p)), Sign::kNegative)
              << "iteration " << iter << ": border arc with a difference on its right";
        }
      }
    }
    ++tested;
  }
  EXPECT_GT(tested, 150);
}

// Triangles sharing a vertex: the sum contains the origin. Faces through the origin are
// tangent and dropped, so every border arc is still a proper minor arc.
TEST(Eme, TouchingTrianglesKeepOnlyProperArcs) {
  std::array<Point3, 6> pts = {Point3{0, 0, 0}, {4, 0, 0},  {0, 4, 0},
                               Point3{0, 0, 0}, {0, 4, 3}, {4, 0, 5}};
  SolidMesh m = two_triangles(pts);
  m.points.erase(m.points.begin() + 3);  // share vertex 0
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  std::vector<uint32_t> s = {0}, o = {1};
  EffectiveMinkowskiEnvelope eme = compute_effective_minkowski_envelope(m, s, o, true);
  ASSERT_FALSE(eme.border.empty());
  for (const auto& e : eme.border) {
    ExactVec x0 = diff(m, e.q0, e.p0), x1 = diff(m, e.q1, e.p1);
    EXPECT_FALSE(exact::is_zero(x0));
    EXPECT_FALSE(exact::is_zero(x1));
    EXPECT_FALSE(exact::parallel(x0, x1));
  }
  for (const auto& f : eme.faces) {
    for (auto [q, p] : f.vertices) EXPECT_NE(q, p) << "a kept face contains the origin";
  }
}

}  // namespace
}  // namespace gvm
