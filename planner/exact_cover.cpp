#include "exact_cover.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

namespace gvm::planner {
namespace {

constexpr size_t kSeed = 32;  // targets in the first K: arcs and points, then the smallest 2-cells

// Arcs, points and the smallest 2-cells first: the targets most likely to decide.
std::vector<uint32_t> seed(std::span<const Target> targets) {
  std::vector<uint32_t> thin, wide;
  for (uint32_t t = 0; t < targets.size(); ++t) {
    (targets[t].reach.dimension() < 2 ? thin : wide).push_back(t);
  }
  std::vector<double> area(targets.size(), 0);
  for (uint32_t t : wide) area[t] = targets[t].reach.area();
  std::stable_sort(wide.begin(), wide.end(), [&](uint32_t a, uint32_t b) { return area[a] < area[b]; });
  thin.insert(thin.end(), wide.begin(), wide.end());
  thin.resize(std::min(thin.size(), kSeed));
  std::sort(thin.begin(), thin.end());
  return thin;
}

// The witnesses of K's overlay, each with every target it serves (K's from the overlay,
// the others tested exactly).
CandidateSet witnesses(std::span<const Target> targets, const std::vector<uint32_t>& k,
                       const std::function<bool(uint32_t, const Direction&)>& serves) {
  std::vector<Target> subset;
  for (uint32_t t : k) subset.push_back(targets[t]);
  CandidateSet out = exact_candidates(subset);
  std::vector<char> in_k(targets.size(), 0);
  for (uint32_t t : k) in_k[t] = 1;
  tbb::parallel_for(size_t{0}, out.candidates.size(), [&](size_t i) {
    Candidate& c = out.candidates[i];
    std::vector<uint32_t> all;
    for (uint32_t local : c.targets) all.push_back(k[local]);
    for (uint32_t t = 0; t < targets.size(); ++t) {
      if (!in_k[t] && serves(t, c.direction)) all.push_back(t);
    }
    std::sort(all.begin(), all.end());
    c.targets = std::move(all);
  });
  return out;
}

CoverProblem problem(uint32_t items, const std::vector<Candidate>& candidates,
                     const std::vector<char>* only = nullptr) {
  CoverProblem p{items, {}};
  for (const Candidate& c : candidates) {
    std::vector<uint32_t> in;
    for (uint32_t t : c.targets) {
      if (!only || (*only)[t]) in.push_back(t);
    }
    p.candidates.push_back(std::move(in));
  }
  return p;
}

}  // namespace

StatusOr<ExactCover> exact_cover(std::span<const Target> targets,
                                 const std::function<bool(uint32_t, const Direction&)>& serves,
                                 const CoverOptions& options) {
  const uint32_t n = static_cast<uint32_t>(targets.size());
  std::vector<uint32_t> k = seed(targets);
  if (k.size() * 4 >= n * 3) {
    k.resize(n);
    std::iota(k.begin(), k.end(), 0u);
  }
  ExactCover out;
  for (;;) {
    ++out.rounds;
    out.overlay_targets = static_cast<uint32_t>(k.size());
    out.candidates = witnesses(targets, k, serves);
    std::vector<char> in_k(n, 0);
    for (uint32_t t : k) in_k[t] = 1;
    // K's own optimum over every direction: its overlay holds every maximal coverage.
    StatusOr<CoverSolution> of_k = solve_set_cover(problem(n, out.candidates.candidates, &in_k), options);
    if (!of_k.ok()) return of_k.status();
    StatusOr<CoverSolution> all = solve_set_cover(problem(n, out.candidates.candidates), options);
    if (!all.ok()) return all.status();
    const bool complete = k.size() == n;
    std::vector<uint32_t> unserved = all->uncoverable;
    if (!complete && !of_k->cancelled && !all->cancelled &&
        (!unserved.empty() || all->chosen.size() > of_k->lower_bound)) {
      // Not proven yet: what K's best cover leaves unserved joins K.
      std::vector<char> served(n, 0);
      for (uint32_t c : of_k->chosen) {
        for (uint32_t t : out.candidates.candidates[c].targets) served[t] = 1;
      }
      for (uint32_t t = 0; t < n; ++t) {
        if (!served[t] && !in_k[t]) unserved.push_back(t);
      }
      const size_t before = k.size();
      for (uint32_t t : unserved) k.push_back(t);
      std::sort(k.begin(), k.end());
      k.erase(std::unique(k.begin(), k.end()), k.end());
      // Nothing new (K's cover was stopped short of its optimum): take every target.
      if (k.size() == before || k.size() * 4 >= n * 3) {
        k.resize(n);
        std::iota(k.begin(), k.end(), 0u);
      }
      continue;
    }
    out.solution = std::move(*all);
    // K's bound and packing hold for every target (K is a subset of them).
    if (of_k->lower_bound > out.solution.lower_bound) {
      out.solution.lower_bound = of_k->lower_bound;
      out.solution.packing = of_k->packing;
    }
    out.solution.optimal = out.solution.chosen.size() == out.solution.lower_bound;
    return out;
  }
}

}  // namespace gvm::planner
