// The planner's exact set cover against exhaustive search: random closed direction sets
// (polygons, non-convex unions and differences, hemispheres, arcs, points, built from
// small integer vectors so that they often touch, cross at vertices and share circles),
// at most 12 of them. The minimum is found by trying every cover made of an independent
// dense candidate set (a Fibonacci lattice and every small integer direction, coverage
// decided by DirectionSet::contains) plus the overlay's witnesses; the planner's count
// must equal it, and each candidate it offers must serve exactly what it says. Within a
// tolerance the same instances against a search over the expanded sets: the dense
// directions, every corner and every planner candidate, each serving the sets within the
// tolerance of it; the planner's count must not exceed that search's minimum, its lower
// bound must not exceed it either (the bound holds for every direction), and each of its
// candidates must serve what it says.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "candidates.h"
#include "gvm/direction_overlay.h"
#include "set_cover.h"
#include "targets.h"
#include "tolerance.h"

namespace gvm::planner {
namespace {

class SetMaker {
 public:
  explicit SetMaker(unsigned seed) : rng_(seed) {}

  Direction small_direction() {
    std::uniform_int_distribution<int> c(-3, 3);
    for (;;) {
      const int x = c(rng_), y = c(rng_), z = c(rng_);
      if (x || y || z) return Direction(x, y, z);
    }
  }

  DirectionSet polygon() {
    const Direction c = small_direction();
    const std::array<double, 3> u = c.unit();
    std::uniform_int_distribution<int> d(-2, 2), count(3, 5);
    std::vector<Direction> normals;
    for (int i = count(rng_); i > 0; --i) {
      normals.emplace_back(std::round(3 * u[0]) + d(rng_), std::round(3 * u[1]) + d(rng_),
                           std::round(3 * u[2]) + d(rng_));
    }
    return DirectionSet::intersection_of_hemispheres(normals);
  }

  DirectionSet any() {
    std::uniform_int_distribution<int> kind(0, 9);
    switch (kind(rng_)) {
      case 0:
        return DirectionSet::hemisphere(small_direction());
      case 1:
      case 2: {
        const Direction a = small_direction(), b = small_direction();
        return parallel(a, b) ? DirectionSet::point(a) : DirectionSet::minor_arc(a, b);
      }
      case 3:
        return DirectionSet::point(small_direction());
      case 4:
        return polygon().union_with(polygon());
      case 5:
        return polygon().difference(polygon());
      case 6:
        return polygon().union_with(DirectionSet::point(small_direction()));
      default:
        return polygon();
    }
  }

 private:
  std::mt19937 rng_;
};

// The fewest of the given coverage masks whose union is `all` (breadth-first over masks).
int minimum_cover(const std::vector<uint32_t>& masks, uint32_t all) {
  std::vector<int> depth(all + 1, -1);
  std::vector<uint32_t> frontier = {0};
  depth[0] = 0;
  for (int d = 0; !frontier.empty(); ++d) {
    std::vector<uint32_t> next;
    for (uint32_t m : frontier) {
      if (m == all) return d;
      for (uint32_t c : masks) {
        const uint32_t n = m | c;
        if (depth[n] < 0) depth[n] = d + 1, next.push_back(n);
      }
    }
    frontier = std::move(next);
  }
  return -1;
}

std::vector<Direction> dense_directions() {
  std::vector<Direction> out = fibonacci_directions(3000);
  for (int x = -3; x <= 3; ++x) {
    for (int y = -3; y <= 3; ++y) {
      for (int z = -3; z <= 3; ++z) {
        if (x || y || z) out.emplace_back(x, y, z);
      }
    }
  }
  return out;
}

TEST(PlannerOptimality, ExactCoverEqualsExhaustiveSearch) {
  const std::vector<Direction> dense = dense_directions();
  int solver_runs = 0, thin = 0;
  for (unsigned seed = 1; seed <= 60; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    SetMaker make(seed);
    std::vector<Target> targets;
    const int n = 4 + static_cast<int>(seed % 9);
    while (static_cast<int>(targets.size()) < n) {
      DirectionSet s = make.any();
      if (s.is_empty()) continue;
      thin += s.dimension() < 2;
      targets.push_back({static_cast<uint32_t>(targets.size()), {}, 0, s, s, s});
    }
    const CandidateSet exact = exact_candidates(targets);
    // Each witness serves exactly the sets it is said to serve.
    std::vector<uint32_t> masks;
    for (const Candidate& c : exact.candidates) {
      uint32_t mask = 0;
      for (uint32_t k = 0; k < targets.size(); ++k) mask |= targets[k].reach.contains(c.direction) << k;
      uint32_t said = 0;
      for (uint32_t k : c.targets) said |= 1u << k;
      ASSERT_EQ(mask, said);
      masks.push_back(mask);
    }
    for (const Direction& d : dense) {
      uint32_t mask = 0;
      for (uint32_t k = 0; k < targets.size(); ++k) mask |= targets[k].reach.contains(d) << k;
      // No direction serves a set of targets that no witness serves.
      EXPECT_TRUE(std::any_of(masks.begin(), masks.end(), [&](uint32_t m) { return (m & mask) == mask; }))
          << "a direction serves " << mask << " beyond every witness";
      masks.push_back(mask);
    }
    const int minimum = minimum_cover(masks, (1u << targets.size()) - 1);
    CoverProblem problem{static_cast<uint32_t>(targets.size()), {}};
    for (const Candidate& c : exact.candidates) problem.candidates.push_back(c.targets);
    auto solution = solve_set_cover(problem, {});
    ASSERT_TRUE(solution.ok());
    EXPECT_EQ(static_cast<int>(solution->chosen.size()), minimum);
    EXPECT_TRUE(solution->optimal);
    EXPECT_TRUE(solution->uncoverable.empty());
    solver_runs += solution->solver_ran;
  }
  EXPECT_GT(thin, 20);  // arcs and points were really part of the instances
  RecordProperty("solver_runs", solver_runs);
}

// The random instances of the exact test, and points placed within about a degree of
// some of their corners (small-integer sets are otherwise too far apart for a tolerance).
std::vector<Target> random_targets_with_near_points(unsigned seed) {
  SetMaker make(seed);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> nudge(-1, 1);
  std::vector<Target> targets;
  auto add = [&](const DirectionSet& s) { targets.push_back({static_cast<uint32_t>(targets.size()), {}, 0, s, s, s}); };
  const int n = 3 + static_cast<int>(seed % 7);
  while (static_cast<int>(targets.size()) < n) {
    DirectionSet s = make.any();
    if (!s.is_empty()) add(s);
  }
  for (int k = 0; k < 3; ++k) {
    const std::vector<Direction> corners = targets[static_cast<size_t>(k) % targets.size()].reach.corners();
    if (corners.empty()) continue;
    const std::array<double, 3> u = corners[static_cast<size_t>(nudge(rng) + 1) % corners.size()].unit();
    add(DirectionSet::point(Direction(std::round(40 * u[0]) + nudge(rng), std::round(40 * u[1]) + nudge(rng),
                                      std::round(40 * u[2]) + nudge(rng))));
  }
  return targets;
}

TEST(PlannerOptimality, CoverWithinAToleranceAgainstSearchOverExpandedSets) {
  std::vector<Direction> dense = dense_directions();
  int fewer_than_exact = 0, proven = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<Target> targets = random_targets_with_near_points(seed);
    // Large enough that sets of small-integer directions come within it of each other.
    const Tolerance tolerance = Tolerance::of(seed % 2 ? 0.0174 : 0.006);
    auto within = [&](uint32_t k, const Direction& d) { return targets[k].reach.within(d, tolerance.near_sin2); };
    const CandidateSet exact = exact_candidates(targets);
    auto cover = tolerance_cover(targets, exact, within, tolerance, {});
    ASSERT_TRUE(cover.ok());
    std::vector<Direction> search = dense;
    for (const Target& t : targets)
      for (const Direction& c : t.reach.corners()) search.push_back(c);
    std::vector<uint32_t> masks;
    for (const Candidate& c : cover->candidates.candidates) {
      uint32_t mask = 0, said = 0;
      for (uint32_t k = 0; k < targets.size(); ++k) mask |= uint32_t(within(k, c.direction)) << k;
      for (uint32_t k : c.targets) said |= 1u << k;
      ASSERT_EQ(mask, said);
      masks.push_back(mask);
    }
    std::vector<uint32_t> searched;
    for (const Direction& d : search) {
      uint32_t mask = 0;
      for (uint32_t k = 0; k < targets.size(); ++k) mask |= uint32_t(within(k, d)) << k;
      searched.push_back(mask);
    }
    const uint32_t all = (1u << targets.size()) - 1;
    const int search_minimum = minimum_cover(searched, all);
    const int count = static_cast<int>(cover->solution.chosen.size());
    EXPECT_LE(count, search_minimum);
    EXPECT_LE(static_cast<int>(cover->solution.lower_bound), search_minimum);
    EXPECT_LE(cover->solution.lower_bound, static_cast<uint32_t>(count));
    // The bound's packing: reach sets pairwise more than twice the tolerance apart.
    const auto& packing = cover->solution.packing;
    for (size_t i = 0; i < packing.size(); ++i)
      for (size_t j = i + 1; j < packing.size(); ++j)
        EXPECT_FALSE(targets[packing[i]].reach.within(targets[packing[j]].reach, tolerance.far_sin2));
    auto exact_solution = solve_set_cover(CoverProblem{static_cast<uint32_t>(targets.size()), [&] {
                                            std::vector<std::vector<uint32_t>> c;
                                            for (const Candidate& e : exact.candidates) c.push_back(e.targets);
                                            return c;
                                          }()},
                                          {});
    ASSERT_TRUE(exact_solution.ok());
    EXPECT_LE(count, static_cast<int>(exact_solution->chosen.size()));
    fewer_than_exact += count < static_cast<int>(exact_solution->chosen.size());
    proven += cover->solution.optimal;
  }
  EXPECT_GT(fewer_than_exact, 3);  // the tolerance really joined sets
  EXPECT_GT(proven, 30);
  RecordProperty("proven", proven);
}

}  // namespace
}  // namespace gvm::planner
