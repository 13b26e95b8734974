// Minimum set cover against exhaustive search, on instances where greedy fails, on sphere
// caps like the planner's, and under time limits, cancellation and concurrent calls.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <thread>
#include <vector>

#include "set_cover.h"

namespace gvm::planner {
namespace {

CoverSolution solve(const CoverProblem& problem, const CoverOptions& options = {}) {
  StatusOr<CoverSolution> solution = solve_set_cover(problem, options);
  EXPECT_TRUE(solution.ok()) << solution.status().message();
  return solution.ok() ? std::move(solution).value() : CoverSolution{};
}

std::vector<uint32_t> items_in_no_candidate(const CoverProblem& problem) {
  std::vector<char> seen(problem.items, 0);
  for (const auto& items : problem.candidates) {
    for (uint32_t i : items) seen[i] = 1;
  }
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < problem.items; ++i) {
    if (!seen[i]) out.push_back(i);
  }
  return out;
}

// What every answer must satisfy, whatever stopped the search: a valid cover of every
// coverable item, the exact uncoverable items, a valid packing, consistent bounds.
void expect_consistent(const CoverProblem& problem, const CoverSolution& s) {
  EXPECT_EQ(s.uncoverable, items_in_no_candidate(problem));
  EXPECT_TRUE(std::is_sorted(s.chosen.begin(), s.chosen.end()));
  EXPECT_EQ(std::adjacent_find(s.chosen.begin(), s.chosen.end()), s.chosen.end());
  std::vector<char> covered(problem.items, 0);
  for (uint32_t c : s.chosen) {
    ASSERT_LT(c, problem.candidates.size());
    for (uint32_t i : problem.candidates[c]) covered[i] = 1;
  }
  for (uint32_t i : s.uncoverable) covered[i] = 1;
  EXPECT_EQ(std::count(covered.begin(), covered.end(), 0), 0) << "an item is left uncovered";

  // No two packing items in one candidate, and every packing item coverable.
  std::vector<char> in_packing(problem.items, 0);
  for (uint32_t i : s.packing) {
    ASSERT_LT(i, problem.items);
    in_packing[i] = 1;
  }
  for (uint32_t c = 0; c < problem.candidates.size(); ++c) {
    const auto& items = problem.candidates[c];
    EXPECT_LE(std::count_if(items.begin(), items.end(), [&](uint32_t i) { return in_packing[i]; }), 1)
        << "packing items share candidate " << c;
  }
  for (uint32_t i : s.uncoverable) EXPECT_FALSE(in_packing[i]);
  EXPECT_LE(s.packing.size(), s.lower_bound);
  EXPECT_LE(s.lower_bound, s.chosen.size());
  EXPECT_LE(s.chosen.size(), s.greedy);
  EXPECT_EQ(s.optimal, s.chosen.size() == s.lower_bound);
  EXPECT_LE(s.lp_bound, s.lower_bound + 1e-6);
}

// Exhaustive search over every subset of candidates: the fewest that cover every coverable
// item. Each subset is a subset of the first half of the candidates joined with one of the
// second half; for each first part, the smallest second part covering the rest is looked up
// among all second parts (meet in the middle, so that 30 candidates stay affordable).
uint32_t minimum_cover_size(const CoverProblem& problem) {
  std::vector<uint32_t> masks;
  uint32_t need = 0;
  for (const auto& items : problem.candidates) {
    uint32_t mask = 0;
    for (uint32_t i : items) mask |= 1u << i;
    masks.push_back(mask);
    need |= mask;
  }
  const size_t half = masks.size() / 2;
  // The items of every subset of candidates [first, first + count), by subset bits.
  auto unions = [&](size_t first, size_t count) {
    std::vector<uint32_t> out(size_t{1} << count, 0);
    for (size_t s = 1; s < out.size(); ++s) {
      out[s] = out[s & (s - 1)] | masks[first + static_cast<size_t>(std::countr_zero(s))];
    }
    return out;
  };
  const std::vector<uint32_t> first = unions(0, half), second = unions(half, masks.size() - half);
  // fewest[x]: the fewest second-half candidates whose items include x. A union holding x
  // holds every part of x, hence the pass from each set down to its subsets.
  std::vector<uint32_t> fewest(size_t{1} << problem.items, UINT32_MAX);
  for (size_t s = 0; s < second.size(); ++s) {
    fewest[second[s]] = std::min<uint32_t>(fewest[second[s]], std::popcount(s));
  }
  for (uint32_t bit = 1; bit < fewest.size(); bit <<= 1) {
    for (uint32_t x = 0; x < fewest.size(); ++x) {
      if (x & bit) fewest[x ^ bit] = std::min(fewest[x ^ bit], fewest[x]);
    }
  }
  uint32_t best = UINT32_MAX;
  for (size_t s = 0; s < first.size(); ++s) {
    const uint32_t rest = fewest[need & ~first[s]];
    if (rest != UINT32_MAX) best = std::min<uint32_t>(best, std::popcount(s) + rest);
  }
  return best;
}

CoverProblem random_small_problem(std::mt19937_64& rng) {
  std::uniform_int_distribution<uint32_t> item_count(1, 14), candidate_count(0, 26);  // + up to 4
  const double densities[] = {0.08, 0.15, 0.3, 0.5};
  const double density = densities[rng() % 4];
  CoverProblem problem;
  problem.items = item_count(rng);
  std::vector<char> hidden(problem.items);
  for (char& h : hidden) h = rng() % 8 == 0;  // about one item in eight uncoverable
  std::bernoulli_distribution in(density);
  for (uint32_t c = candidate_count(rng); c > 0; --c) {
    std::vector<uint32_t>& items = problem.candidates.emplace_back();
    for (uint32_t i = 0; i < problem.items; ++i) {
      if (!hidden[i] && in(rng)) items.push_back(i);
    }
  }
  // Duplicates and subsets of other candidates, at random places (before or after them).
  for (int extra = static_cast<int>(rng() % 5); extra > 0 && !problem.candidates.empty(); --extra) {
    std::vector<uint32_t> copy = problem.candidates[rng() % problem.candidates.size()];
    if (rng() % 2) std::erase_if(copy, [&](uint32_t) { return rng() % 3 == 0; });
    const auto at = static_cast<long>(rng() % problem.candidates.size());
    problem.candidates.insert(problem.candidates.begin() + at, std::move(copy));
  }
  return problem;
}

TEST(SetCover, RandomInstancesMatchExhaustiveSearch) {
  const uint64_t seed = 20240611;
  std::mt19937_64 rng(seed);
  int searched = 0;
  for (int trial = 0; trial < 400; ++trial) {
    SCOPED_TRACE(testing::Message() << "seed " << seed << ", trial " << trial);
    const CoverProblem problem = random_small_problem(rng);
    const uint32_t minimum = minimum_cover_size(problem);
    const CoverSolution s = solve(problem);
    expect_consistent(problem, s);
    EXPECT_EQ(s.chosen.size(), minimum);
    EXPECT_TRUE(s.optimal);
    EXPECT_EQ(s.lower_bound, minimum);
    EXPECT_FALSE(s.cancelled || s.time_limit_reached);
    searched += s.solver_ran;
  }
  // Some instances must reach the solver, or the exact search went untested here.
  EXPECT_GT(searched, 0);
}

// Rows R1, R2 split 14 items in halves; columns S1, S2, S3 (2, 4, 8 items) split each row
// evenly. Greedy takes S3 (8 > 7), then S2, then S1: three, where R1 and R2 suffice. Links
// (two items from different rows and columns) give every item its own candidate set, so
// that the reductions cannot merge items in one cell and undo the trap.
CoverProblem greedy_trap() {
  // a1..a7 = items 0..6 in R1, b1..b7 = items 7..13 in R2; column of a_k and b_k:
  // k = 1 -> S1, k = 2, 3 -> S2, k = 4..7 -> S3.
  auto a = [](uint32_t k) { return k - 1; };
  auto b = [](uint32_t k) { return k + 6; };
  CoverProblem p;
  p.items = 14;
  p.candidates = {
      {a(1), a(2), a(3), a(4), a(5), a(6), a(7)},  // 0: R1
      {b(1), b(2), b(3), b(4), b(5), b(6), b(7)},  // 1: R2
      {a(1), b(1)},                                // 2: S1
      {a(2), a(3), b(2), b(3)},                    // 3: S2
      {a(4), a(5), a(6), a(7), b(4), b(5), b(6), b(7)},  // 4: S3
      {a(4), b(1)}, {a(5), b(2)}, {a(6), b(3)}, {a(7), b(1)},  // links
      {a(1), b(4)}, {a(2), b(5)}, {a(3), b(6)}, {a(1), b(7)},
  };
  for (auto& items : p.candidates) std::sort(items.begin(), items.end());
  return p;
}

TEST(SetCover, GreedyTrapIsSolvedBySearch) {
  const CoverProblem problem = greedy_trap();
  ASSERT_EQ(minimum_cover_size(problem), 2u);
  const CoverSolution s = solve(problem);
  expect_consistent(problem, s);
  EXPECT_EQ(s.greedy, 3u);
  EXPECT_TRUE(s.solver_ran);
  EXPECT_EQ(s.chosen, (std::vector<uint32_t>{0, 1}));
  EXPECT_TRUE(s.optimal);
  EXPECT_EQ(s.reduced_items, 14u);  // nothing merged
  EXPECT_EQ(s.reduced_candidates, 13u);
}

// Vertex cover of odd cycles: the items are edges, the candidates vertices. A packing (a
// matching) has (n-1)/2 edges but a cover needs (n+1)/2 vertices, so only the solver's bound
// proves optimality; each cycle is a component and the bounds add up.
TEST(SetCover, OddCyclesNeedTheSolversBound) {
  CoverProblem p;
  uint32_t first = 0;
  uint32_t expected = 0;
  for (uint32_t n : {5u, 7u, 9u}) {
    for (uint32_t v = 0; v < n; ++v) {
      const uint32_t left = first + (v + n - 1) % n, right = first + v;  // edges at vertex v
      p.candidates.push_back({std::min(left, right), std::max(left, right)});
    }
    first += n;
    expected += (n + 1) / 2;
  }
  p.items = first;
  const CoverSolution s = solve(p);
  expect_consistent(p, s);
  EXPECT_EQ(s.components, 3u);
  EXPECT_TRUE(s.solver_ran);
  EXPECT_EQ(s.chosen.size(), expected);
  EXPECT_EQ(s.lower_bound, expected);
  EXPECT_EQ(s.packing.size(), expected - 3);
  EXPECT_TRUE(s.optimal);
  EXPECT_NEAR(s.lp_bound, (5 + 7 + 9) / 2.0, 1e-6);
}

TEST(SetCover, TrivialAndInvalidProblems) {
  const CoverSolution empty = solve({});
  EXPECT_TRUE(empty.chosen.empty() && empty.optimal && !empty.solver_ran);

  CoverProblem none;
  none.items = 3;
  none.candidates = {{}, {}};
  const CoverSolution s = solve(none);
  EXPECT_EQ(s.uncoverable, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_TRUE(s.chosen.empty() && s.optimal);

  CoverProblem unsorted;
  unsorted.items = 3;
  unsorted.candidates = {{2, 0, 2}, {1}};
  const CoverSolution u = solve(unsorted);
  EXPECT_EQ(u.chosen, (std::vector<uint32_t>{0, 1}));
  EXPECT_EQ(u.forced, 2u);

  CoverProblem bad;
  bad.items = 2;
  bad.candidates = {{0, 2}};
  const StatusOr<CoverSolution> r = solve_set_cover(bad, {});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidArgument);
}

// What the planner sees: features visible within caps of directions (radii 30 to 90
// degrees) and candidate directions sampled on the sphere; a direction covers the features
// whose cap holds it. Greedy is not optimal on these, and the LP bound not tight.
CoverProblem sphere_caps(uint64_t seed, uint32_t features, uint32_t directions) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  auto unit = [&] {
    double x = normal(rng), y = normal(rng), z = normal(rng);
    const double n = std::sqrt(x * x + y * y + z * z);
    return std::array<double, 3>{x / n, y / n, z / n};
  };
  std::uniform_real_distribution<double> radius(30.0, 90.0);
  std::vector<std::array<double, 3>> axes(features);
  std::vector<double> min_cos(features);
  for (uint32_t f = 0; f < features; ++f) {
    axes[f] = unit();
    min_cos[f] = std::cos(radius(rng) * 3.14159265358979323846 / 180.0);
  }
  CoverProblem p;
  p.items = features;
  for (uint32_t d = 0; d < directions; ++d) {
    const auto u = unit();
    std::vector<uint32_t>& items = p.candidates.emplace_back();
    for (uint32_t f = 0; f < features; ++f) {
      if (u[0] * axes[f][0] + u[1] * axes[f][1] + u[2] * axes[f][2] >= min_cos[f]) items.push_back(f);
    }
  }
  return p;
}

TEST(SetCover, SphereCapsSolveOptimallyAndDeterministically) {
  const uint64_t seed = 7;
  SCOPED_TRACE(testing::Message() << "seed " << seed);
  const CoverProblem problem = sphere_caps(seed, 400, 3000);
  const CoverSolution first = solve(problem);
  expect_consistent(problem, first);
  EXPECT_TRUE(first.optimal);
  EXPECT_TRUE(first.solver_ran);
  const CoverSolution second = solve(problem);
  EXPECT_EQ(first.chosen, second.chosen);
  EXPECT_EQ(first.packing, second.packing);
  EXPECT_EQ(first.lower_bound, second.lower_bound);
  EXPECT_EQ(first.nodes, second.nodes);
  std::printf("[          ] sphere caps: 400 x 3000 -> %u items x %u candidates in %u components "
              "(%u forced); greedy %u, optimum %zu, packing %zu, LP %.3f, %llu nodes, solver %s, "
              "%.3f s\n",
              first.reduced_items, first.reduced_candidates, first.components, first.forced,
              first.greedy, first.chosen.size(), first.packing.size(), first.lp_bound,
              static_cast<unsigned long long>(first.nodes), first.solver_ran ? "ran" : "not needed",
              first.seconds);
}

TEST(SetCover, ConcurrentCallsGiveTheSequentialResults) {
  const CoverProblem a = sphere_caps(11, 300, 2000), b = sphere_caps(12, 300, 2000);
  const CoverSolution a_alone = solve(a), b_alone = solve(b);
  CoverSolution a_together, b_together;
  std::thread other([&] { b_together = solve(b); });
  a_together = solve(a);
  other.join();
  EXPECT_EQ(a_alone.chosen, a_together.chosen);
  EXPECT_EQ(a_alone.lower_bound, a_together.lower_bound);
  EXPECT_EQ(a_alone.nodes, a_together.nodes);
  EXPECT_EQ(b_alone.chosen, b_together.chosen);
  EXPECT_EQ(b_alone.lower_bound, b_together.lower_bound);
  EXPECT_EQ(b_alone.nodes, b_together.nodes);
  expect_consistent(a, a_together);
  expect_consistent(b, b_together);
  EXPECT_TRUE(a_alone.solver_ran && b_alone.solver_ran);  // both contend for the solver
}

// Random set covering with no structure (like the OR-library's scp sets): large enough that
// proving optimality takes the solver much longer than the limits below.
CoverProblem hard_random(uint64_t seed) {
  std::mt19937_64 rng(seed);
  CoverProblem p;
  p.items = 300;
  std::bernoulli_distribution in(0.02);
  for (int c = 0; c < 1500; ++c) {
    std::vector<uint32_t>& items = p.candidates.emplace_back();
    for (uint32_t i = 0; i < p.items; ++i) {
      if (in(rng)) items.push_back(i);
    }
  }
  return p;
}

TEST(SetCover, TimeLimitReturnsAValidCover) {
  const uint64_t seed = 3;
  SCOPED_TRACE(testing::Message() << "seed " << seed);
  const CoverProblem problem = hard_random(seed);
  CoverOptions options;
  options.time_limit_seconds = 0.5;
  const CoverSolution s = solve(problem, options);
  expect_consistent(problem, s);
  EXPECT_FALSE(s.cancelled);
  // Nothing but the limit stops an unfinished search.
  EXPECT_TRUE(s.optimal || s.time_limit_reached);
  std::printf("[          ] time limit 0.5 s: greedy %u, chosen %zu, bound %u, packing %zu, %llu nodes, "
              "limit %s, %.3f s\n",
              s.greedy, s.chosen.size(), s.lower_bound, s.packing.size(),
              static_cast<unsigned long long>(s.nodes), s.time_limit_reached ? "reached" : "not reached",
              s.seconds);
}

TEST(SetCover, CancelFromAnotherThreadReturnsAValidCover) {
  const uint64_t seed = 4;
  SCOPED_TRACE(testing::Message() << "seed " << seed);
  const CoverProblem problem = hard_random(seed);
  std::atomic<bool> cancel{false};
  CoverOptions options;
  options.cancelled = [&] { return cancel.load(); };
  CoverSolution s;
  std::thread solver([&] { s = solve(problem, options); });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto cancelled_at = std::chrono::steady_clock::now();
  cancel = true;
  solver.join();
  const std::chrono::duration<double> latency = std::chrono::steady_clock::now() - cancelled_at;
  expect_consistent(problem, s);
  EXPECT_TRUE(s.cancelled || s.optimal);
  EXPECT_FALSE(s.time_limit_reached);
  std::printf("[          ] cancel: returned %.3f s after the cancel; chosen %zu, bound %u, "
              "%llu nodes\n",
              latency.count(), s.chosen.size(), s.lower_bound, static_cast<unsigned long long>(s.nodes));
}

// One search runs at a time: a call waiting for the solver still honours its cancel.
TEST(SetCover, CancelWhileWaitingForTheSolver) {
  const CoverProblem busy = hard_random(5), waiting = greedy_trap();
  std::atomic<bool> stop_busy{false}, stop_waiting{false};
  CoverOptions busy_options, waiting_options;
  busy_options.cancelled = [&] { return stop_busy.load(); };
  waiting_options.cancelled = [&] { return stop_waiting.load(); };
  CoverSolution busy_result, waiting_result;
  std::thread busy_thread([&] { busy_result = solve(busy, busy_options); });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // usually holds the solver by now
  std::thread waiting_thread([&] { waiting_result = solve(waiting, waiting_options); });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  stop_waiting = true;
  waiting_thread.join();
  stop_busy = true;
  busy_thread.join();
  expect_consistent(waiting, waiting_result);
  expect_consistent(busy, busy_result);
  // Had it got the solver first, the trap would be solved before the cancel.
  EXPECT_TRUE(waiting_result.cancelled || waiting_result.optimal);
  EXPECT_TRUE(busy_result.cancelled || busy_result.optimal);
}

// Wherever the search stops, the answer stays a valid cover with a valid bound: cancels
// after a growing number of polls (the polls come at fixed points of the search, so these
// stops are reproducible), and short time limits.
TEST(SetCover, StoppingAnywhereKeepsTheBoundValid) {
  const uint64_t seed = 7;
  SCOPED_TRACE(testing::Message() << "seed " << seed);
  const CoverProblem problem = sphere_caps(seed, 400, 3000);
  const CoverSolution full = solve(problem);
  ASSERT_TRUE(full.optimal);
  const size_t optimum = full.chosen.size();
  for (uint64_t polls : {1, 10, 100, 1000, 10000, 100000}) {
    SCOPED_TRACE(testing::Message() << "cancelled at poll " << polls);
    uint64_t count = 0;
    CoverOptions options;
    options.cancelled = [&] { return ++count >= polls; };
    const CoverSolution s = solve(problem, options);
    expect_consistent(problem, s);
    EXPECT_LE(s.lower_bound, optimum);
    EXPECT_TRUE(s.cancelled || s.optimal);
  }
  for (double limit : {0.01, 0.05, 0.2}) {
    SCOPED_TRACE(testing::Message() << "time limit " << limit);
    CoverOptions options;
    options.time_limit_seconds = limit;
    const CoverSolution s = solve(problem, options);
    expect_consistent(problem, s);
    EXPECT_LE(s.lower_bound, optimum);
    EXPECT_TRUE(s.time_limit_reached || s.optimal);
  }
}

TEST(SetCover, CancelledBeforeStartReturnsGreedy) {
  const CoverProblem problem = greedy_trap();
  CoverOptions options;
  options.cancelled = [] { return true; };
  const CoverSolution s = solve(problem, options);
  expect_consistent(problem, s);
  EXPECT_TRUE(s.cancelled);
  EXPECT_FALSE(s.solver_ran);
  EXPECT_EQ(s.chosen.size(), 3u);
  EXPECT_EQ(s.lower_bound, 2u);
  EXPECT_FALSE(s.optimal);
}

}  // namespace
}  // namespace gvm::planner
