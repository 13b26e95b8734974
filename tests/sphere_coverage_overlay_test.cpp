// The N-way coverage overlay against brute force: every cell's witness has exactly the
// cell's coverage (membership decided by each set on its own), and the maximal coverage
// sets are maximal, distinct and cover every coverage that occurs.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "sphere/coverage_overlay.h"
#include "sphere/local_visibility_map.h"
#include "sphere/set_operations.h"
#include "sphere_random_images.h"

namespace gvm::sphere {
namespace {

using exact::ExactVec;
using testing::iv;
using Kind = CoverageOverlay::CellKind;

std::vector<uint32_t> brute_coverage(const std::vector<SphericalImage>& sets, const ExactVec& u) {
  std::vector<uint32_t> out;
  for (size_t k = 0; k < sets.size(); ++k) {
    if (sets[k].contains(u)) out.push_back(static_cast<uint32_t>(k));
  }
  return out;
}

// On a boundary arc, a curve or a point of some set: never true inside a face.
bool on_some_set_boundary(const std::vector<SphericalImage>& sets, const ExactVec& u) {
  for (const SphericalImage& s : sets) {
    if (testing::on_face_boundary(s, u)) return true;
    for (const Arc& a : s.curves()) {
      if (arc_contains(a, u)) return true;
    }
    for (const ExactVec& p : s.points()) {
      if (exact::same_direction(p, u)) return true;
    }
  }
  return false;
}

bool includes(const std::vector<uint32_t>& big, const std::vector<uint32_t>& small) {
  return std::includes(big.begin(), big.end(), small.begin(), small.end());
}

struct Visited {
  Kind kind;
  uint32_t index;
  std::vector<uint32_t> coverage;
  bool operator==(const Visited& o) const {
    return std::tie(kind, index, coverage) == std::tie(o.kind, o.index, o.coverage);
  }
};

std::vector<Visited> visit_all(const CoverageOverlay& o) {
  std::vector<Visited> out;
  o.for_each_cell([&](const CoverageOverlay::Cell& c) {
    out.push_back({c.kind, c.index, {c.coverage.begin(), c.coverage.end()}});
  });
  return out;
}

// Checks every cell against brute force (every `stride`-th cell only, for big inputs),
// each index once, and the maximal sets against all the coverages seen.
void check_overlay(const std::vector<SphericalImage>& sets, size_t stride = 1) {
  const CoverageOverlay o(sets);
  ASSERT_EQ(o.set_count(), sets.size());
  std::vector<std::vector<bool>> seen = {std::vector<bool>(o.vertex_count()), std::vector<bool>(o.edge_count()),
                                         std::vector<bool>(o.face_count())};
  std::vector<std::vector<uint32_t>> coverages;
  size_t cell = 0;
  o.for_each_cell([&](const CoverageOverlay::Cell& c) {
    auto& s = seen[static_cast<int>(c.kind)];
    ASSERT_LT(c.index, s.size());
    ASSERT_FALSE(s[c.index]) << "cell visited twice";
    s[c.index] = true;
    const std::vector<uint32_t> cov(c.coverage.begin(), c.coverage.end());
    ASSERT_TRUE(std::is_sorted(cov.begin(), cov.end()));
    ASSERT_TRUE(std::adjacent_find(cov.begin(), cov.end()) == cov.end());
    coverages.push_back(cov);
    if (cell++ % stride != 0) return;
    ASSERT_EQ(cov, brute_coverage(sets, c.witness)) << "cell kind " << int(c.kind) << " index " << c.index;
    if (c.kind == Kind::kFace) ASSERT_FALSE(on_some_set_boundary(sets, c.witness));
  });
  for (const auto& s : seen) ASSERT_TRUE(std::all_of(s.begin(), s.end(), [](bool b) { return b; }));

  const std::vector<CoverageOverlay::MaximalCoverage> maximal = o.maximal_coverage();
  for (size_t i = 0; i < maximal.size(); ++i) {
    const auto& m = maximal[i];
    ASSERT_FALSE(m.coverage.empty());
    ASSERT_EQ(m.coverage, brute_coverage(sets, m.witness));
    for (size_t j = 0; j < maximal.size(); ++j) {
      if (i != j) ASSERT_FALSE(includes(maximal[j].coverage, m.coverage)) << i << " in " << j;
    }
  }
  for (const auto& cov : coverages) {
    if (cov.empty()) continue;
    ASSERT_TRUE(std::any_of(maximal.begin(), maximal.end(), [&](const auto& m) { return includes(m.coverage, cov); }));
  }
  // Deterministic: the same input gives the same cells and maximal sets, in order.
  const CoverageOverlay again(sets);
  ASSERT_EQ(visit_all(o), visit_all(again));
  const auto maximal_again = again.maximal_coverage();
  ASSERT_EQ(maximal.size(), maximal_again.size());
  for (size_t i = 0; i < maximal.size(); ++i) {
    ASSERT_EQ(maximal[i].coverage, maximal_again[i].coverage);
    ASSERT_TRUE(exact::same_direction(maximal[i].witness, maximal_again[i].witness));
  }
}

TEST(SphereCoverageOverlay, RandomSetsEveryCellAgainstBruteForce) {
  constexpr uint64_t kBaseSeed = 77001;
  for (uint64_t i = 0; i < 60; ++i) {
    const uint64_t seed = kBaseSeed + i;
    SCOPED_TRACE("seed " + std::to_string(seed));
    std::mt19937_64 rng(seed);
    std::vector<SphericalImage> sets;
    const int n = testing::uniform(rng, 1, 12);
    for (int k = 0; k < n; ++k) {
      // Now and then a general face with holes: the difference of two sets.
      sets.push_back(testing::uniform(rng, 0, 4) == 0
                         ? set_difference(testing::random_image(rng), testing::random_image(rng))
                         : testing::random_image(rng));
    }
    check_overlay(sets);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

// 300 sets: far more layers than a word of bits, every set on its own layer.
TEST(SphereCoverageOverlay, ThreeHundredSets) {
  constexpr uint64_t kSeed = 4242;
  SCOPED_TRACE("seed " + std::to_string(kSeed));
  std::mt19937_64 rng(kSeed);
  std::vector<SphericalImage> sets;
  for (int k = 0; k < 300; ++k) {
    sets.push_back(k % 10 == 9 ? testing::random_image(rng) : testing::random_lvm(rng));
  }
  check_overlay(sets, 4);
}

TEST(SphereCoverageOverlay, NoBoundaries) {
  {
    const CoverageOverlay o(std::vector<SphericalImage>{});
    EXPECT_TRUE(o.maximal_coverage().empty());
  }
  {
    const std::vector<SphericalImage> sets = {SphericalImage::empty(), SphericalImage::empty()};
    EXPECT_TRUE(CoverageOverlay(sets).maximal_coverage().empty());
  }
  const std::vector<SphericalImage> sets = {SphericalImage::full_sphere(), SphericalImage::empty(),
                                            SphericalImage::full_sphere()};
  const CoverageOverlay o(sets);
  const auto maximal = o.maximal_coverage();
  ASSERT_EQ(maximal.size(), 1u);
  EXPECT_EQ(maximal[0].coverage, (std::vector<uint32_t>{0, 2}));
  check_overlay(sets);
}

TEST(SphereCoverageOverlay, TouchingAndDegenerateSets) {
  // Squares around +z sharing an edge and a corner, hemispheres meeting on the equator,
  // points shared by three sets, antipodal points, a great circle through them, and a set
  // of two overlapping faces (coverage counted twice, member once).
  auto sq = [](int x0, int y0, int x1, int y1) {
    std::vector<ExactVec> n = {iv(1, 0, -x0), iv(-1, 0, x1), iv(0, 1, -y0), iv(0, -1, y1)};
    return local_visibility_map(n);
  };
  SphericalImage pts;
  pts.add_point(iv(1, 1, 0));
  pts.add_point(iv(-1, -1, 0));
  SphericalImage one_point;
  one_point.add_point(iv(1, 1, 0));
  const std::vector<SphericalImage> sets = {
      sq(-2, -1, 0, 1), sq(0, -1, 2, 1), sq(2, 1, 3, 2),
      SphericalImage::hemisphere(iv(0, 0, 1)), SphericalImage::hemisphere(iv(0, 0, -1)),
      pts, one_point, SphericalImage::great_circle(iv(1, -1, 10)),
      testing::combine({sq(-1, -1, 1, 1), sq(0, 0, 2, 2)})};
  check_overlay(sets);
  const auto maximal = CoverageOverlay(sets).maximal_coverage();
  auto has = [&](std::vector<uint32_t> s) {
    return std::any_of(maximal.begin(), maximal.end(), [&](const auto& m) { return m.coverage == s; });
  };
  EXPECT_TRUE(has({3, 4, 5, 6, 7}));    // (1, 1, 0): both hemispheres, points, circle
  EXPECT_TRUE(has({0, 1, 3, 8}));       // the shared edge of the squares, inside set 8
  EXPECT_TRUE(has({1, 2, 3, 8}));       // the corner (2, 1) of squares 1 and 2, in set 8
}

}  // namespace
}  // namespace gvm::sphere
